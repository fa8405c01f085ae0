#!/usr/bin/env python3
"""Order 2 against order 1: the contact force per refinement on the four benchmarks with
references (docs/validation.md §15), and mmg against pdas on the same order-2 problem.

    tests/benchmarks/order2_table.py build/bin

Every row runs `fosls-contact solve` on the shipped example with mesh.refinements r and
mesh.order 1 and 2 (mmg, tolerance 1e-8), and pdas at order 2 up to refinements 4. About 5
minutes on two cores.
"""
import json
import os
import subprocess
import sys
import tempfile

CASES = [("hertz", 0.0125226, "Hertz λ = 1"), ("hertz_incompressible", 0.0214937, "Hertz λ = ∞"),
         ("signorini_square", 0.083366, "square λ = 1"),
         ("signorini_square_incompressible", 0.136701, "square λ = ∞")]


def solve(bindir, case, refinements, order, method, workdir):
    case = json.loads(json.dumps(case))
    case["mesh"].update({"refinements": refinements, "order": order})
    case.setdefault("solver", {}).update({"method": method, "tolerance": 1e-8})
    path, out = os.path.join(workdir, "case.json"), os.path.join(workdir, "result.json")
    with open(path, "w") as f:
        json.dump(case, f)
    subprocess.run([os.path.join(bindir, "fosls-contact"), "solve", path, "-o", out],
                   capture_output=True, check=False)
    with open(out) as f:
        return json.load(f)


def cell(result, ref, with_time=False):
    force = result["contact"]["force"][1]
    text = f"{result['dofs']:,}".replace(",", " ")
    text += f", {100 * (abs(force) - ref) / ref:+.4f} %, {result['iterations']}"
    return text + (f", {result['timing']['total_s']:.2f} s" if with_time else "")


def main():
    bindir = sys.argv[1] if len(sys.argv) > 1 else "build/bin"
    print("| case | refinements | order 1: unknowns, error, iterations | "
          "order 2: unknowns, error, iterations, time | order 2 pdas − mmg (relative) |")
    print("|---|---:|---|---|---:|")
    with tempfile.TemporaryDirectory() as workdir:
        for name, ref, label in CASES:
            example = subprocess.run([os.path.join(bindir, "fosls-contact"), "example", name],
                                     capture_output=True, text=True, check=True).stdout
            case = json.loads(example)
            for r in range(1, 6):
                one = solve(bindir, case, r, 1, "mmg", workdir)
                two = solve(bindir, case, r, 2, "mmg", workdir)
                agreement = ""
                if r <= 4:
                    exact = solve(bindir, case, r, 2, "pdas", workdir)["contact"]["force"][1]
                    agreement = f"{abs(two['contact']['force'][1] - exact) / abs(exact):.1e}"
                print(f"| {label} | {r} | {cell(one, ref)} | {cell(two, ref, True)} | "
                      f"{agreement} |", flush=True)


if __name__ == "__main__":
    main()
