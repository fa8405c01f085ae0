#!/usr/bin/env python3
"""Robustness of the multilevel solver on cases set up as users set them up.

Each case in tests/robustness/cases is solved as given (the solver section left to its
defaults, weights included) by mmg, tnnmg and pdas, to a tolerance of 1e-8. The checks:
no refusal, every method converges, the contact force of mmg and tnnmg equals pdas's to
1e-6 relative, and the iteration counts stay within the bounds below. The bounds are counts
(deterministic), not times.

    robustness.py --bin build/bin/fosls-contact CASE...      check (ctest)
    robustness.py --bin build/bin/fosls-contact --table CASE...   print the Markdown table
    robustness.py ... --plain ...   the same with "acceleration": "none" (the plain method; the
                                    bounds are then not checked)
    robustness.py ... --friction 0.3 ...   Coulomb friction 𝔣 = 0.3 on every contact group, mmg
                                    and pdas (ctest label friction_robustness)
    robustness.py ... --repeat 3 ...   wall times: the shortest of 3 runs each
    robustness.py ... --refinements=-1,0,1 ...   each case also at refinements one below and
                                    one above its own (a row per case and level)
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

METHODS = ("mmg", "tnnmg", "pdas")
# Iteration bounds per method, with the default subspace acceleration (docs/method.md §4.5);
# the target is 40 for mmg on every case. Measured: mmg 11–17, tnnmg 7–11 except the
# L-bracket (79: its linear correction on the inactive set converges slowly there, while mmg on
# the same hierarchy takes 17), pdas 2–10.
BOUNDS = {"mmg": 25, "tnnmg": 25, "pdas": 12}
CASE_BOUNDS = {("l_bracket", "tnnmg"): 100}
# With --friction (Coulomb on every contact group; tnnmg does not handle friction): the issue's
# target, 40, for mmg and pdas on every case. Where mmg's Coulomb iteration stalls, pdas finishes
# from its iterate (solvers/coulomb_fallback.hpp, docs/method.md §8.4): mmg's count is then the
# iterations before the switch plus pdas's after it, both printed, and the cases where it
# switches are asserted, so that a change of the stall test shows (docs/validation.md §13,
# "Robustness cases with Coulomb friction").
FRICTION_METHODS = ("mmg", "pdas")
FRICTION_BOUNDS = {"mmg": 40, "pdas": 40}
FRICTION_CASE_BOUNDS = {}
# Case: the iteration after which pdas took over (measured; mmg alone took 67, 66, 36 and 33),
# asserted within FALLBACK_SLACK: where the residual's plateau sits near the stall test's
# threshold (the L-bracket's 0.88), round-off moves the switch by an iteration between machines
# (OpenBLAS picks its kernels for the CPU at run time: 18 on one, 19 on another).
FALLBACK_SLACK = 2
FRICTION_FALLBACK = {
    "incompressible_cylinder_punch": 34,
    "thin_strip_incompressible": 15,
    "l_bracket": 18,
    "tilted_plane_block": 15,
}
# 3D cases ("dimension": 3; mmg and pdas only): the 3D issue's target for mmg, 40. Measured:
# mmg 17–24, pdas 4–7 over the cases' own and one more refinement (docs/validation.md §16).
METHODS_3D = ("mmg", "pdas")
BOUNDS_3D = {"mmg": 40, "pdas": 12}


def solve(binary, case, method, workdir, plain, repeat=1):
    """The result of one solve, with wall_s the shortest of `repeat` identical runs (the least
    disturbed by other work on the machine)."""
    best = None
    for _ in range(repeat):
        r = solve_once(binary, case, method, workdir, plain)
        if "error" in r:
            return r
        if best is None or r["wall_s"] < best["wall_s"]:
            best = r
    return best


def solve_once(binary, case, method, workdir, plain):
    case = json.loads(json.dumps(case))
    solver = case.setdefault("solver", {})
    solver.update({"method": method, "tolerance": 1e-8, "max_iterations": 400})
    if plain:
        solver["acceleration"] = "none"
    path = os.path.join(workdir, f"case_{method}.json")
    out = os.path.join(workdir, f"result_{method}.json")
    with open(path, "w") as f:
        json.dump(case, f)
    start = time.monotonic()
    run = subprocess.run([binary, "solve", path, "--out", out, "--quiet"],
                         capture_output=True, text=True)
    wall = time.monotonic() - start
    if run.returncode not in (0, 3, 4):
        return {"error": (run.stderr or run.stdout).strip().splitlines()[-1:]}
    with open(out) as f:
        result = json.load(f)
    result["wall_s"] = wall
    return result


def iterations(result):
    """The iteration count, as "mmg + pdas" where pdas finished a stalled Coulomb solve."""
    switched = (result.get("friction") or {}).get("fallback_after")
    if switched:
        return f"{switched} + {result['iterations'] - switched} (pdas)"
    return str(result["iterations"])


def load_case(path, friction=0.0):
    """The case at `path`, ready to be solved from a temporary folder (a mesh file it names is
    next to the case: its path made absolute), with Coulomb friction of coefficient `friction`
    on every contact group when it is > 0."""
    with open(path) as f:
        case = json.load(f)
    for key in ("geo_file", "msh_file"):
        if key in case["mesh"]:
            case["mesh"][key] = os.path.join(os.path.dirname(os.path.abspath(path)),
                                             case["mesh"][key])
    if friction > 0:
        for condition in case["boundary"].values():
            if condition["type"] == "contact":
                condition["friction"] = {"coefficient": friction}
    return case


def check_case(binary, path, table_rows, plain, repeat=1, offset=0, friction=0.0):
    name = os.path.splitext(os.path.basename(path))[0]
    case = load_case(path, friction)
    methods, bounds = METHODS, BOUNDS
    if case.get("dimension") == 3:
        methods, bounds = METHODS_3D, BOUNDS_3D
    if friction > 0:
        methods, bounds = FRICTION_METHODS, FRICTION_BOUNDS
    if offset:
        case["mesh"]["refinements"] = case["mesh"].get("refinements", 0) + offset
        name += f" (refinements {case['mesh']['refinements']})"
    failures = []
    results = {}
    with tempfile.TemporaryDirectory() as workdir:
        for method in methods:
            results[method] = solve(binary, case, method, workdir, plain, repeat)
    for method, r in results.items():
        if "error" in r:
            failures.append(f"{method}: refused or failed: {r['error']}")
        elif not r["converged"] and not plain:
            failures.append(f"{method}: not converged ({r['stop_reason']})")
    if failures:
        return name, failures
    reference = results["pdas"]["contact"]["force"]
    scale = math.hypot(*reference)
    for method in methods:
        r = results[method]
        if plain:
            continue
        diff = math.hypot(*(a - b for a, b in zip(r["contact"]["force"], reference)))
        if diff > 1e-6 * scale:
            failures.append(f"{method}: force {r['contact']['force']} differs from pdas "
                            f"{reference} by {diff / scale:.2e} relative")
        bound = (FRICTION_CASE_BOUNDS if friction else CASE_BOUNDS).get((name, method),
                                                                         bounds[method])
        if r["iterations"] > bound:
            failures.append(f"{method}: {r['iterations']} iterations > {bound}")
    if friction and not offset and not plain:
        switched = results["mmg"]["friction"]["fallback_after"]
        expected = FRICTION_FALLBACK.get(name)
        if (switched is None) != (expected is None) or (
                expected is not None and abs(switched - expected) > FALLBACK_SLACK):
            failures.append(f"mmg: pdas took over after {switched} iterations, expected "
                            f"{expected} (± {FALLBACK_SLACK})")
    mmg = results["mmg"]
    weights = (f"{mmg['weights']['c3']:.3g} ({mmg['weights']['c3_limit']:.3g})"
               if "weights" in mmg else "0.1 (3D: fixed)")
    table_rows.append(
        f"| {name} | {mmg['dofs']:,} | {mmg['levels']} | {weights} | "
        + " | ".join(f"{iterations(results[m])} its, {results[m]['wall_s']:.1f} s"
                     + (f", {results[m]['memory']['peak_mib']:.0f} MiB" if friction else "")
                     + ("" if results[m]["converged"] else " (not converged)")
                     for m in methods)
        + f" | {mmg['asymptotic_rate']:.2f} |")
    return name, failures


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bin", required=True)
    parser.add_argument("--table", action="store_true")
    parser.add_argument("--plain", action="store_true")
    parser.add_argument("--refinements", default="0",
                        help="offsets added to each case's mesh.refinements, e.g. -1,0,1")
    parser.add_argument("--repeat", type=int, default=1,
                        help="run each solve this many times and report the shortest wall time")
    parser.add_argument("--friction", type=float, default=0.0,
                        help="Coulomb friction of this coefficient on every contact group "
                             "(methods mmg and pdas)")
    parser.add_argument("cases", nargs="+")
    args = parser.parse_args()
    rows = []
    failed = False
    offsets = [int(o) for o in args.refinements.split(",")]
    for path in args.cases:
        for offset in offsets:
            name, failures = check_case(args.bin, path, rows, args.plain, args.repeat, offset,
                                        args.friction)
            for f in failures:
                print(f"FAIL {name}: {f}")
            failed |= bool(failures)
            if not failures:
                print(f"ok {name}")
    if args.table:
        print()
        methods = FRICTION_METHODS if args.friction > 0 else METHODS
        if all(json.load(open(p)).get("dimension") == 3 for p in args.cases):
            methods = METHODS_3D
        print("| case | unknowns | levels | c3 (limit) | " + " | ".join(methods) + " | mmg rate |")
        print("|---|---|---|---|" + "---|" * len(methods) + "---|")
        print("\n".join(rows))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
