#!/usr/bin/env python3
"""The 3D time guide against measured solves, side by side in one run.

Usage: OMP_NUM_THREADS=1 tests/benchmarks/time_estimate_3d.py build/bin [refinements ...]
                                                                     [--cases CASE.json ...]

For the shipped `hertz_3d` half ball at λ = 1 and λ = ∞ at the given refinements (default 1 2 3,
none when only cases are given),
then for each CASE.json as it is (its .geo files next to it), and each method with an estimate
(mmg, tnnmg, pdas), prints what `fosls-contact estimate` says and what `fosls-contact solve` took: the
wall time and the CPU time (user + sys, from /usr/bin/time) of the whole process, its peak memory
and the solver's iterations. With one thread the CPU time is what the solve costs a quiet core;
the ratio estimate / CPU is the column to read (docs/performance.md, "3D: the time guide").
"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

# TIME_ESTIMATE_METHODS=mmg,pdas runs fewer.
METHODS = os.environ.get("TIME_ESTIMATE_METHODS", "mmg,tnnmg,pdas").split(",")


def estimates(binary, case_path):
    text = subprocess.run([binary, "estimate", case_path], capture_output=True, text=True).stdout
    out = {}
    for line in text.splitlines():
        m = re.match(r"\s+(mmg|tnnmg|pdas)\s+.*about ([0-9.]+) (s|min|h)", line)
        if m:
            factor = {"s": 1, "min": 60, "h": 3600}[m.group(3)]
            out[m.group(1)] = float(m.group(2)) * factor
    return out


def timed_solve(binary, case_path, result_path):
    start = time.time()
    run = subprocess.run(["/usr/bin/time", "-f", "%U %S %M", binary, "solve", case_path,
                          "--out", result_path, "-q"], capture_output=True, text=True)
    wall = time.time() - start
    user, sys_s, peak_kib = run.stderr.strip().splitlines()[-1].split()
    with open(result_path) as f:
        result = json.load(f)
    return wall, float(user) + float(sys_s), int(peak_kib) / 1024, result.get("iterations"), \
        result.get("dofs")


def print_rows(binary, label, case, case_path):
    with open(case_path, "w") as f:
        json.dump(case, f)
    guide = estimates(binary, case_path)
    for method in METHODS:
        case["solver"] = {**case.get("solver", {}), "method": method}
        with open(case_path, "w") as f:
            json.dump(case, f)
        wall, cpu, peak, iterations, unknowns = timed_solve(
            binary, case_path, os.path.join(os.path.dirname(case_path), "result.json"))
        est = guide.get(method, float("nan"))
        print(f"| {label} | {method} | {unknowns} | {est:.3g} | {wall:.2f} | {cpu:.2f} | "
              f"{est / cpu:.2f} | {peak:.0f} | {iterations} |", flush=True)


def main():
    bindir = sys.argv[1]
    args = sys.argv[2:]
    cases = args[args.index("--cases") + 1:] if "--cases" in args else []
    args = args[:args.index("--cases")] if "--cases" in args else args
    refinements = [int(r) for r in args] or ([] if cases else [1, 2, 3])
    binary = os.path.abspath(os.path.join(bindir, "fosls-contact"))
    base = json.loads(subprocess.run([binary, "example", "hertz_3d"], capture_output=True,
                                     text=True).stdout)
    print("| case | method | unknowns | estimate s | wall s | CPU s | estimate / CPU | peak MiB |"
          " iterations |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for lam in [1, "inf"]:
            for r in refinements:
                case = json.loads(json.dumps(base))
                case["material"]["lambda"] = lam
                case["mesh"]["refinements"] = r
                label = f"hertz_3d λ = {'∞' if lam == 'inf' else lam}, refinements {r}"
                print_rows(binary, label, case, os.path.join(tmp, "case.json"))
        for path in cases:
            with open(path) as f:
                case = json.load(f)
            # Beside the .geo files it may name.
            for geo in glob.glob(os.path.join(os.path.dirname(os.path.abspath(path)), "*.geo")):
                shutil.copy(geo, tmp)
            name = os.path.basename(path)[:-5]
            print_rows(binary, f"{name}, refinements {case['mesh'].get('refinements', 0)}", case,
                       os.path.join(tmp, "case.json"))


if __name__ == "__main__":
    main()
