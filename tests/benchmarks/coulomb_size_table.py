#!/usr/bin/env python3
"""Benchmark (not a test): time and memory per load step of Coulomb against frictionless at a
given size (issue 49; docs/performance.md, "Friction").

The shipped cattaneo_mindlin (pressed by 0.01, then shifted by 0.001 and 0.002, each step from
the previous one) at each refinement: without friction, with Coulomb 𝔣 = 0.3 by mmg (which may
hand a stalled step to pdas, docs/method.md §8.4), and with `--pdas` by pdas, whose force per
step is compared with mmg's. One `fosls-contact solve` after the other, never two at once, so
the three columns of a row are measured side by side; the times are only comparable within a
row. Set OMP_NUM_THREADS for the runs as for every benchmark here.

With `--against OTHER` (another build's fosls-contact; repeatable) the Coulomb run only, each
OTHER's then FOSLS_CONTACT's, one row each (a binary may be written VAR=VALUE,...@BINARY to run
it with those environment variables): iterations per step (mmg + the fallback's pdas after a switch),
the multilevel cycles spent (mmg's iterations plus the inexact pdas's cycles per Newton step
times its iterations; the nested iteration's not counted), seconds per step, peak MiB and the
force difference to OTHER's per step.

usage: coulomb_size_table.py FOSLS_CONTACT REFINEMENTS... [--pdas | --against OTHER...]
"""
import json
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "validation"))
import validation_lib as vl  # noqa: E402  (runs fosls-contact on a case dict)


def case(binary, refinements, friction, method):
    c = json.loads(subprocess.run([binary, "example", "cattaneo_mindlin"],
                                  capture_output=True, text=True, check=True).stdout)
    c["mesh"]["refinements"] = refinements
    c.setdefault("solver", {})["method"] = method
    for condition in c["boundary"].values():
        if condition["type"] == "contact":
            if friction:
                condition["friction"] = {"coefficient": 0.3}
            else:
                condition.pop("friction", None)
    return c


def cell(result):
    """Iterations per step (with where pdas took over), seconds per step, peak MiB."""
    steps = result["load_steps"]["steps"]
    its = []
    for s in steps:
        switched = (s.get("friction") or {}).get("fallback_after")
        its.append(f"{s['iterations']}" + (f" ({switched} + pdas)" if switched else "")
                   + ("" if s["converged"] else " not converged"))
    seconds = "/".join(f"{s['timing']['solve_s'] + s['timing']['setup_s']:.1f}" for s in steps)
    return f"{'/'.join(its)}, {seconds} s, {result['memory']['peak_mib']:.0f} MiB"


def fallback_cycles(step):
    """The inexact pdas's cycles per Newton step from the coulomb_fallback warning (0: exact).
    Only the experiment's binary (commit c5ec94b, reverted; docs/performance.md "Friction") says
    so in its warning; with main's the cycles equal the iterations."""
    for w in step.get("warning_details", []):
        if w["code"] == "coulomb_fallback":
            m = re.search(r"pdas with (\d+) multilevel cycle", w["message"])
            return int(m.group(1)) if m else 0
    return 0


def cycles_cell(result):
    """Iterations (mmg + pdas) and multilevel cycles per step."""
    its, cycles = [], []
    for s in result["load_steps"]["steps"]:
        switched = (s.get("friction") or {}).get("fallback_after")
        pdas = s["iterations"] - switched if switched else 0
        its.append(f"{switched} + {pdas}" if switched else f"{s['iterations']}")
        cycles.append(str(s["iterations"] - pdas + fallback_cycles(s) * pdas))
    return "/".join(its), "/".join(cycles)


def binary_and_environment(run):
    """`run` is a binary, or VAR=VALUE,...@BINARY: the binary and the environment to run it in
    (the caller's with those variables set)."""
    settings, _, binary = run.rpartition("@")
    env = dict(os.environ)
    env.update(s.split("=", 1) for s in settings.split(",") if s)
    return binary, env


def solve_with_environment(run, refinements):
    """Coulomb 0.3 by `run` (binary_and_environment)."""
    binary, env = binary_and_environment(run)
    return vl.solve(binary, case(binary, refinements, True, "mmg"), allow_unconverged=True,
                    env=env)


def against(runs, refinements):
    """Coulomb 0.3 by each of `runs`, one row each."""
    print("| refinements | binary | iterations (mmg + pdas) | cycles | s per step | peak MiB | "
          "force difference to the first row |")
    print("|---|---|---|---|---|---|---|")
    for r in refinements:
        first = None
        for b in runs:
            res = solve_with_environment(b, r)
            first = first or res
            steps = res["load_steps"]["steps"]
            its, cycles = cycles_cell(res)
            seconds = "/".join(f"{s['timing']['solve_s'] + s['timing']['setup_s']:.1f}"
                               for s in steps)
            print(f"| {r} | {b} | {its} | {cycles} | {seconds} | "
                  f"{res['memory']['peak_mib']:.0f} | {force_difference(res, first)} |", flush=True)


def force_difference(a, b):
    """Relative difference of the contact force per step, "/"-separated, a step that either
    solve did not converge marked."""
    cells = []
    for sa, sb in zip(a["load_steps"]["steps"], b["load_steps"]["steps"]):
        fa, fb = sa["contact"]["force"], sb["contact"]["force"]
        d = math.hypot(*(x - y for x, y in zip(fa, fb))) / math.hypot(*fb)
        cells.append(f"{d:.1e}" + ("" if sa["converged"] and sb["converged"] else " (unconverged)"))
    return "/".join(cells)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(args) < 2:
        print(__doc__)
        return 2
    binary, with_pdas = args[0], "--pdas" in sys.argv
    if "--against" in sys.argv:
        others = [sys.argv[i + 1] for i, a in enumerate(sys.argv) if a == "--against"]
        against(others + [binary], [int(r) for r in args[1:] if r not in others])
        return 0
    print("| refinements | unknowns | frictionless | Coulomb 0.3, mmg | Coulomb 0.3, pdas | "
          "mmg − pdas in force, per step |")
    print("|---|---|---|---|---|---|")
    for refinements in (int(r) for r in args[1:]):
        frictionless = vl.solve(binary, case(binary, refinements, False, "mmg"),
                                allow_unconverged=True)
        mmg = vl.solve(binary, case(binary, refinements, True, "mmg"), allow_unconverged=True)
        pdas = (vl.solve(binary, case(binary, refinements, True, "pdas"), allow_unconverged=True)
                if with_pdas else None)
        print(f"| {refinements} | {mmg['dofs']:,} | {cell(frictionless)} | {cell(mmg)} | "
              + (f"{cell(pdas)} | {force_difference(mmg, pdas)} |" if pdas else "— | — |"),
              flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
