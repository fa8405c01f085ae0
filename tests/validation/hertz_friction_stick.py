#!/usr/bin/env python3
"""The stick zone of the compressible hertz_friction under pure normal loading, over refinements
(docs/validation.md §13, "Compressible: the stick zone under pure normal loading").

With ν = 0.3 (Dundurs' β ≠ 0) pressing alone makes the ends of the contact slip inwards and
friction holds a central stick zone (Spence 1975). Per refinement: the stick zone (the result's,
from the slip, docs/result-format.md; the shipped example with ν = 0.3 and without its shift) against the contact width, the same solution's stick zone
read as before issue 49 (|σ_nt| below the bound 𝔣p), and the edges where the two differ.

usage: hertz_friction_stick.py FOSLS_CONTACT [--method mmg|pdas] [refinements ...]
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validation_lib as vl  # noqa: E402  (runs fosls-contact on a case dict)

F = 0.3


def main():
    args = sys.argv[1:]
    method = "mmg"
    if "--method" in args:
        method = args[args.index("--method") + 1]
        del args[args.index("--method"):args.index("--method") + 2]
    binary, levels = args[0], [int(r) for r in args[1:]] or [3, 4, 5]
    print("| refinements | method | iterations | stick zone length | contact width | stick / width "
          "| by \\|σ_nt\\| (before): length, / width | slipping below the bound | F_y |")
    print("|---:|---|---:|---:|---:|---:|---|---:|---:|")
    for r in levels:
        case = json.loads(subprocess.run([binary, "example", "hertz_friction"], capture_output=True,
                                         text=True, check=True).stdout)
        case["mesh"]["refinements"] = r
        # As in the table of docs/validation.md: E = 2.6, ν = 0.3 (μ = 1, λ = 1.5), pressed by
        # 0.01 without a shift, tolerance 1e-9.
        case["material"] = {"mu": 1, "lambda": 1.5}
        case["boundary"]["top"]["displacement"] = [0, -0.01]
        case["solver"] = dict(case.get("solver", {}), tolerance=1e-9)
        case.setdefault("solver", {})["method"] = method
        result = vl.solve(binary, case, allow_unconverged=True)
        c = result["contact"]
        largest = F * max(c["pressure"])
        before = sum(l for s, p, l, on in zip(c["shear"], c["pressure"], c["length"], c["active"])
                     if on and abs(s) < F * p - 1e-4 * largest)
        width = c["zone"]["width"]
        stick = c["stick_zone"]["length"]
        print(f"| {r} | {method} | {result['iterations']}"
              f"{'' if result['converged'] else ' (not converged)'} | {stick:.5f} | {width:.5f} | "
              f"{stick / width:.3f} | {before:.5f}, {before / width:.3f} | "
              f"{c['stick_zone'].get('slipping_below_bound')} | {c['force'][1]:.7f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
