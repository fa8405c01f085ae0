#!/usr/bin/env python3
"""Benchmark (not a test): Coulomb's nested iteration side by side (issue 49; docs/performance.md,
"Friction", "Coulomb's nested iteration").

The shipped cattaneo_mindlin (pressed by 0.01 in step 0, then shifted by 0.001 and 0.002 in steps
1 and 2, each from the previous step's solution) at the given refinements: without friction
(the first binary), then with it by each binary given (e.g. main's and a branch's
`fosls-contact`). Per run: iterations per step (press/shift/shift), the nested iteration's
iterations per coarser level of the press step, set-up plus solve seconds per step, and c/a of
the shift steps' stick zones. One process at a time; iterations are deterministic, times only
comparable within one run of this script (set OMP_NUM_THREADS=1).

usage: coulomb_nested_table.py NAME=FOSLS_CONTACT [NAME=FOSLS_CONTACT ...] [refinements=2,3,4,5]
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "validation"))
import validation_lib as vl  # noqa: E402  (runs fosls-contact on a case dict)
from cattaneo_mindlin import shipped  # noqa: E402  (the shipped case at a refinement)


def stick_ratio(step):
    """c/a: half the stick zone's length over half the contact width."""
    c = step["contact"]
    return c["stick_zone"]["length"] / c["zone"]["width"]


def row(result):
    steps = result["load_steps"]["steps"]
    its = "/".join(str(s["iterations"]) + ("" if s["converged"] else " (not converged)")
                   for s in steps)
    nested = "/".join(str(n) for n in steps[0]["solver_statistics"].get("nested_iterations", []))
    seconds = "/".join(f"{s['timing']['setup_s'] + s['timing']['solve_s']:.1f}" for s in steps)
    ca = "/".join(f"{stick_ratio(s):.3f}" for s in steps[1:])
    return its, nested, seconds, ca


def main():
    runs = [a.split("=", 1) for a in sys.argv[1:] if not a.startswith("refinements=")]
    levels = [a[len("refinements="):] for a in sys.argv[1:] if a.startswith("refinements=")]
    levels = [int(v) for v in (levels[0] if levels else "2,3,4,5").split(",")]
    if not runs:
        print(__doc__)
        return 2
    print("| refinements | run | iterations per step | nested iterations (press) | "
          "s per step | c/a (shifts) |")
    print("|---|---|---|---|---|---|")
    for r in levels:
        base = shipped(runs[0][1], r)
        plain = json.loads(json.dumps(base))
        del plain["boundary"]["contact"]["friction"]
        for name, binary, case in [("frictionless", runs[0][1], plain)] + \
                [(n, b, base) for n, b in runs]:
            its, nested, seconds, ca = row(vl.solve(binary, case, allow_unconverged=True))
            print(f"| {r} | {name} | {its} | {nested} | {seconds} | {ca} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
