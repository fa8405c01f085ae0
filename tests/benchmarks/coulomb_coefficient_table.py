#!/usr/bin/env python3
"""Benchmark (not a test): Coulomb's iterations per load step against the friction coefficient
(issue 49; docs/validation.md, "Coulomb: iterations against the coefficient").

The shipped cattaneo_mindlin (pressed by 0.01 in step 0, then shifted by 0.001 and 0.002 in
steps 1 and 2, each from the previous step's solution) is solved at the given refinements with
each coefficient 𝔣, and once without friction on the same mesh. Each solve is one
`fosls-contact solve` run after the other (never two at once); the iterations are
deterministic, the times only comparable within one run of this script.

usage: coulomb_coefficient_table.py FOSLS_CONTACT [refinements=5] [coefficients=0.1,0.2,...,1.0]
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "validation"))
import validation_lib as vl  # noqa: E402  (runs fosls-contact on a case dict)


def argument(name, fallback):
    for a in sys.argv[2:]:
        if a.startswith(name + "="):
            return a[len(name) + 1:]
    return fallback


def shipped(binary, refinements):
    c = json.loads(subprocess.run([binary, "example", "cattaneo_mindlin"],
                                  capture_output=True, text=True, check=True).stdout)
    c["mesh"]["refinements"] = refinements
    return c


def steps(result):
    """Per load step: (iterations, converged, solve seconds)."""
    return [(s["iterations"], s["converged"], s["timing"]["solve_s"])
            for s in result["load_steps"]["steps"]]


def cell(rows):
    its = "/".join(f"{i}" + ("" if ok else " (not converged)") for i, ok, _ in rows)
    return its, sum(t for _, _, t in rows)


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    binary = sys.argv[1]
    refinements = int(argument("refinements", "5"))
    coefficients = [float(f) for f in argument(
        "coefficients", "0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9,1.0").split(",")]
    base = shipped(binary, refinements)
    plain = json.loads(json.dumps(base))
    del plain["boundary"]["contact"]["friction"]
    free = steps(vl.solve(binary, plain, allow_unconverged=True))
    free_its, free_s = cell(free)
    print(f"refinements {refinements}; frictionless iterations per step (press/shift/shift) "
          f"{free_its}, solve {free_s:.1f} s\n")
    print("| 𝔣 | iterations per step (press/shift/shift) | largest / frictionless | "
          "all converged | solve s |")
    print("|---:|---|---:|---|---:|")
    for f in coefficients:
        c = json.loads(json.dumps(base))
        c["boundary"]["contact"]["friction"] = {"coefficient": f}
        rows = steps(vl.solve(binary, c, allow_unconverged=True))
        its, seconds = cell(rows)
        ratio = max(i / max(1, fi) for (i, _, _), (fi, _, _) in zip(rows, free))
        print(f"| {f:g} | {its} | {ratio:.2f} | {'yes' if all(ok for _, ok, _ in rows) else 'no'} "
              f"| {seconds:.1f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
