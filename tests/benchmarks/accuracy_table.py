#!/usr/bin/env python3
"""The contact force to a requested accuracy: FOSLS's accuracy loop against the displacement FEM.

Two tables, in one run on this machine (docs/validation.md §14, docs/performance.md
"Accuracy on demand"):

1. **Efficiency** of the force error estimate (solver/strategy/force_accuracy.hpp): per level of the
   accuracy loop (`"accuracy": {"force": 1e-9}`, which is never reached, so every level up to
   --finest is solved), the estimate, the true error against the reference and their ratio, for
   Hertz λ = 1 and ∞, the Signorini square λ = 1 and ∞ and the L-shaped corner case.
2. **Time to a requested accuracy**: the whole process's wall time to reach |F − F_ref| / F_ref ≤
   tol for (a) `fosls-contact solve` with `"accuracy": {"force": tol}` and the default options,
   (b) the same with the recommended volumetric weight (c2_volumetric 0.5 at λ = 1, 2 at
   λ = ∞, docs/method.md §2.2), (c) `fosls-bench-displacement` (P1 at λ = 1, the mixed element at
   λ = ∞) at the coarsest refinement whose force is within tol — chosen knowing the reference,
   which a user does not have, so (c) is the displacement FEM at its best; and (d) (a) with
   `"mesh": {"order": 2}`, the order-2 space (docs/method.md §10).

The efficiency table has the order-2 levels too (up to --order2-finest).

    tests/benchmarks/accuracy_table.py build/bin [--finest 6] [--fem-finest 6] [--order2-finest 5]

References (docs/validation.md §12, §14): Hertz λ = 1 0.0125226, λ = ∞ 0.0214937 (body normal);
the Signorini square λ = 1 0.083366, λ = ∞ 0.136701; the L-shape 0.0142673.
"""
import argparse
import json
import math
import os
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

CASES = {
    "Hertz λ = 1": ("hertz", 0.0125226, 2, "p1"),
    "Hertz λ = ∞": ("hertz_incompressible", 0.0214937, 2, "mixed"),
    "square λ = 1": ("signorini_square", 0.083366, 2, "p1"),
    "square λ = ∞": ("signorini_square_incompressible", 0.136701, 2, "mixed"),
    "L-shape λ = 1": ("lshape", 0.0142673, 1, "p1"),
}


def load_case(bindir, name):
    if name == "lshape":
        with open(os.path.join(ROOT, "tests/validation/lshape_corner.json")) as f:
            case = json.load(f)
        del case["adaptivity"]
        return case
    out = subprocess.run([os.path.join(bindir, "fosls-contact"), "example", name], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def run_json(cmd, case, workdir):
    path = os.path.join(workdir, "case.json")
    with open(path, "w") as f:
        json.dump(case, f)
    out = os.path.join(workdir, "result.json")
    if os.path.exists(out):
        os.remove(out)  # the displacement FEM prints its result instead
    t0 = time.perf_counter()
    proc = subprocess.run(cmd(path, out), capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if proc.returncode not in (0, 3, 4):
        raise RuntimeError(proc.stderr)
    if os.path.exists(out):
        with open(out) as f:
            return json.load(f), wall
    return json.loads(proc.stdout), wall


def fosls(bindir, case, refinements, tol, max_dofs, weights=None, workdir=".", order=1):
    case = json.loads(json.dumps(case))
    case["mesh"]["refinements"] = refinements
    case["mesh"]["order"] = order
    case.setdefault("solver", {}).pop("tolerance", None)
    case["accuracy"] = {"force": tol, "max_dofs": max_dofs}
    if weights:
        case["weights"] = dict(case.get("weights", {}), **weights)
    exe = os.path.join(bindir, "fosls-contact")
    return run_json(lambda p, o: [exe, "solve", p, "-o", o], case, workdir)


def fem(bindir, case, refinements, element, workdir):
    case = json.loads(json.dumps(case))
    case["mesh"]["refinements"] = refinements
    exe = os.path.join(bindir, "fosls-bench-displacement")
    return run_json(lambda p, o: [exe, p, "--element", element], case, workdir)


def magnitude(force):
    return math.hypot(force[0], force[1])


def efficiency_table(bindir, finest, order2_finest, workdir):
    """Per level: force, true error, estimate, ratio and efficiency, for both orders."""
    print("| case | order | refinements | unknowns | force | true error | estimate | ratio ρ | "
          "estimate / error |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for (label, (name, ref, start, _)), order in [(c, o) for o in (1, 2) for c in CASES.items()]:
        last = finest if order == 1 else order2_finest
        first = start if order == 1 else 1
        result, _ = fosls(bindir, load_case(bindir, name), first, 1e-9, 2_000_000, None, workdir,
                          order)
        for s in result["accuracy"]["steps"]:
            if s["refinements"] > last:
                break
            force = magnitude(s["force"])
            error = abs(force - ref) / ref
            est = s["estimate"]
            ratio = f"{s['ratio']:.2f}{'' if s['ratio_observed'] else ' (assumed)'}" \
                if s["ratio"] is not None else ""
            print(f"| {label} | {order} | {s['refinements']} | {s['dofs']:,} | {force:.7f} | "
                  f"{100 * error:.3f} % | "
                  f"{'' if est is None else f'{100 * est:.3f} %'} | {ratio} | "
                  f"{'' if est is None else f'{est / error:.2f}'} |".replace(",", " "))


def fem_at_best(bindir, case, ref, tol, element, fem_finest, workdir, start):
    for r in range(start, fem_finest + 1):
        result, wall = fem(bindir, case, r, element, workdir)
        error = abs(magnitude(result["force"]) - ref) / ref
        if error <= tol:
            return r, error, wall, result["dofs"]
    return None


def time_table(bindir, tolerances, fem_finest, max_dofs, workdir):
    print("| case | tol | (a) default: time, error, levels | (b) c2_volumetric: time, error | "
          "(d) order 2: time, error, levels | "
          "(c) displacement FEM: time, error, refinements | (c)/(a) | (c)/(b) | (c)/(d) |")
    print("|---|---:|---|---|---|---|---:|---:|---:|")
    for label, (name, ref, start, element) in CASES.items():
        if name == "lshape":
            continue
        case = load_case(bindir, name)
        lam_inf = element == "mixed"
        for tol in tolerances:
            cells = []
            times = []
            variants = [(None, 1), ({"c2_volumetric": 2.0 if lam_inf else 0.5}, 1), (None, 2)]
            for weights, order in variants:
                result, wall = fosls(bindir, case, start, tol, max_dofs, weights, workdir, order)
                a = result["accuracy"]
                error = abs(magnitude(result["contact"]["force"]) - ref) / ref
                levels = f"r{a['steps'][0]['refinements']}–{a['steps'][-1]['refinements']}"
                note = "" if a["reached"] else f", NOT reached ({a['stop_reason']})"
                cells.append(f"{wall:.2f} s, {100 * error:.3f} %, {levels}{note}")
                times.append(wall if a["reached"] and error <= 2 * tol else None)
            best = fem_at_best(bindir, case, ref, tol, element, fem_finest, workdir, start)
            if best:
                r, error, wall, dofs = best
                cells.append(f"{wall:.2f} s, {100 * error:.3f} %, r{r} ({dofs:,} unknowns)"
                             .replace(",", " "))
                ratios = [f"{wall / t:.2f}" if t else "—" for t in times]
            else:
                cells.append(f"not within tol up to refinements {fem_finest}")
                ratios = ["—", "—", "—"]
            print(f"| {label} | {100 * tol:g} % | " + " | ".join(cells) + " | " +
                  " | ".join(ratios) + " |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("bindir")
    parser.add_argument("--finest", type=int, default=6)
    parser.add_argument("--fem-finest", type=int, default=6)
    parser.add_argument("--order2-finest", type=int, default=5)
    parser.add_argument("--max-dofs", type=int, default=8_000_000)
    parser.add_argument("--tolerances", default="5e-4,1e-4")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as workdir:
        print("Efficiency of the force error estimate (accuracy.force 1e-9: every level solved)\n")
        efficiency_table(args.bindir, args.finest, args.order2_finest, workdir)
        print("\nTime to a requested force accuracy (wall time of the whole process)\n")
        tolerances = [float(t) for t in args.tolerances.split(",")]
        time_table(args.bindir, tolerances, args.fem_finest, args.max_dofs, workdir)


if __name__ == "__main__":
    main()
