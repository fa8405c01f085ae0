#!/usr/bin/env python3
"""Hertz's contact force from FOSLS and from an independent displacement FEM, both λ, in one run.

For the shipped `hertz` (λ = 1) and `hertz_incompressible` (λ = ∞) cases at mesh.refinements
coarsest..finest: FOSLS (`fosls-contact solve`, tolerance 1e-9) and the displacement FEM of
tests/benchmarks/displacement_fem.cpp (`fosls-bench-displacement`: plain P1 for λ = 1 only, as
it locks at λ = ∞, and the mixed P1-iso-P2/P1 element for both) on the same meshes. Prints one
Markdown table per λ: per refinement the unknowns, force and wall time of each method, then the
interval that the finest FOSLS and mixed forces span. Where the two sequences approach each
other monotonically from opposite sides, that interval contains the limit as long as they stay
monotone under further refinement (an assumption, not a proof): its midpoint is the reference,
half its width the uncertainty (docs/validation.md §12).

    tests/benchmarks/displacement_reference.py build/bin [--coarsest 2] [--finest 6]

Refinements 7 need about 20 GB and half an hour on two cores (the mixed element's sparse LU).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def example(bindir, name):
    return json.loads(subprocess.run([os.path.join(bindir, "fosls-contact"), "example", name],
                                     check=True, capture_output=True, text=True).stdout)


def write(case, workdir):
    path = os.path.join(workdir, "case.json")
    with open(path, "w") as f:
        json.dump(case, f)
    return path


def fosls(bindir, case, workdir):
    case = dict(case, solver=dict(case["solver"], tolerance=1e-9))
    out = os.path.join(workdir, "result.json")
    run = subprocess.run([os.path.join(bindir, "fosls-contact"), "solve", write(case, workdir),
                          "--out", out, "--quiet"], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"fosls-contact: exit {run.returncode}: {run.stderr}")
    with open(out) as f:
        r = json.load(f)
    return {"dofs": r["dofs"], "force": r["contact"]["force"][1], "time_s": r["timing"]["total_s"]}


def displacement(bindir, case, element, workdir):
    run = subprocess.run([os.path.join(bindir, "fosls-bench-displacement"), write(case, workdir),
                          "--element", element], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"fosls-bench-displacement {element}: exit {run.returncode}: {run.stderr}")
    r = json.loads(run.stdout)
    return {"dofs": r["dofs"], "force": r["force"][1], "time_s": r["total_s"]}


def thousands(n):
    return f"{n:,}".replace(",", " ")


def monotone(values):
    steps = [b - a for a, b in zip(values, values[1:])]
    return all(s > 0 for s in steps) or all(s < 0 for s in steps)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("bindir", help="the build's bin directory")
    parser.add_argument("--coarsest", type=int, default=2)
    parser.add_argument("--finest", type=int, default=6)
    args = parser.parse_args()
    levels = range(args.coarsest, args.finest + 1)
    with tempfile.TemporaryDirectory() as workdir:
        for name, lam, elements in (("hertz", "1", ("p1", "mixed")),
                                    ("hertz_incompressible", "∞", ("mixed",))):
            case = example(args.bindir, name)
            columns = {"FOSLS": []}
            columns.update({e: [] for e in elements})
            for r in levels:
                case["mesh"]["refinements"] = r
                columns["FOSLS"].append(fosls(args.bindir, case, workdir))
                for e in elements:
                    columns[e].append(displacement(args.bindir, case, e, workdir))
            print(f"\nHertz λ = {lam}: contact force per refinement (unknowns, wall time)\n")
            print("| refinements | " + " | ".join(columns) + " |")
            print("|---:|" + "---:|" * len(columns))
            for k, r in enumerate(levels):
                cells = [f"{c[k]['force']:.7f} ({thousands(c[k]['dofs'])}, {c[k]['time_s']:.1f} s)"
                         for c in columns.values()]
                print(f"| {r} | " + " | ".join(cells) + " |")
            a = [x["force"] for x in columns["FOSLS"]]
            b = [x["force"] for x in columns["mixed"]]
            low, high = sorted((a[-1], b[-1]))
            # One sequence rising, the other falling, and the rising one still below: if both
            # stay monotone under further refinement, their common limit lies between them.
            rising, falling = (a, b) if a[-1] > a[0] else (b, a)
            brackets = (monotone(a) and monotone(b) and (a[-1] - a[0]) * (b[-1] - b[0]) < 0
                        and rising[-1] <= falling[-1])
            mid, half = (low + high) / 2, (high - low) / 2
            print(f"\nλ = {lam}: finest FOSLS and mixed forces span [{low:.7f}, {high:.7f}]: "
                  f"{mid:.7f} ± {half:.1e} ({100 * half / mid:.4f} %); "
                  + ("both monotone from opposite sides: if they stay so, the limit lies inside"
                     if brackets else "they do not bracket the limit: no reference from them"))


if __name__ == "__main__":
    main()
