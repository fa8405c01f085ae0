#!/usr/bin/env python3
"""adaptive_steps_side_by_side.py BASE_BIN NEW_BIN [--rounds N] [--dir DIR] [--cases c,...]

The table of docs/performance.md "The accuracy loop's solver levels a uniform factor apart": the
2D Hertz cases (lambda = 1 and inf) to a force accuracy of 5e-4 from refinements 2 with mmg,
uniform and adaptive levels with BASE_BIN and NEW_BIN, alternately in one script (one thread,
/usr/bin/time -v: CPU time = user + sys, peak resident set). The true error is against the
references of docs/validation.md section 12. Then, per level of NEW_BIN's adaptive runs (first
round): unknowns, estimate, true error and efficiency (estimate / true error), for
validation.md section 14.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

REFERENCE = {"hertz": 0.0125226, "hertz_incompressible": 0.0214937}
# name: the accuracy section's levels (force 5e-4 is added)
VARIANTS = {"uniform": {"refinement": "uniform"}, "adaptive": {"refinement": "adaptive"}}


def case_file(binary, case, variant, directory, label):
    d = json.loads(subprocess.run([binary, "example", case], check=True, capture_output=True,
                                  text=True).stdout)
    d["mesh"]["refinements"] = 2
    d["accuracy"] = {"force": 5e-4, **VARIANTS[variant]}
    d["solver"] = {"method": "mmg"}
    path = os.path.join(directory, f"{case}_{variant}_{label}.json")
    with open(path, "w") as f:
        json.dump(d, f)
    return path


def run(label, binary, case, variant, directory, levels_out):
    path = case_file(binary, case, variant, directory, label)
    out = path.replace(".json", "_result.json")
    timing = path.replace(".json", "_time.txt")
    with open(timing, "w") as err:
        subprocess.run(["/usr/bin/time", "-v", binary, "solve", path, "--out", out, "-q"],
                       stdout=subprocess.DEVNULL, stderr=err, env={**os.environ,
                                                                   "OMP_NUM_THREADS": "1"})
    t = open(timing).read()
    cpu = sum(float(re.search(k + r" \(seconds\): ([0-9.]+)", t).group(1))
              for k in ("User time", "System time"))
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([0-9:.]+)", t).group(1)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): ([0-9]+)", t).group(1))
    r = json.load(open(out))
    a = r["accuracy"]
    ref = REFERENCE[case]
    force = abs(r["contact"]["force"][1])
    true_error = abs(force - ref) / ref
    steps = a["steps"]
    print(f"| {case} | {variant}, {label} | {cpu:.2f} | {wall} | {rss / 1024:.0f} | {len(steps)} | "
          f"{r['dofs']} | {a['reached']} | {fmt(a['estimate'])} | {100 * true_error:.4f} % | "
          f"{', '.join(str(s['iterations']) for s in steps)} |", flush=True)
    for s in steps:
        e = abs(abs(s["force"][1]) - ref) / ref
        est = s["estimate"]
        levels_out.append(f"| {case} | {variant}, {label} | {s['dofs']} | {fmt(est)} | {100 * e:.4f} % | "
                          f"{'—' if est is None else f'{est / e:.2f}'} |")


def fmt(x):
    return "—" if x is None else f"{100 * x:.4f} %"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("base")
    p.add_argument("new")
    p.add_argument("--rounds", type=int, default=2)
    p.add_argument("--dir", default=None)
    p.add_argument("--cases", default="hertz,hertz_incompressible")
    args = p.parse_args()
    directory = args.dir or tempfile.mkdtemp()
    os.makedirs(directory, exist_ok=True)
    print(os.popen("uptime").read().strip())
    print("| case | levels | CPU s | wall | peak MiB | solves | last unknowns | reached | estimate | "
          "true error | iterations per solve |")
    print("|---|---|---:|---:|---:|---:|---:|---|---:|---:|---|")
    levels = []
    for rnd in range(args.rounds):
        for case in args.cases.split(","):
            for label, binary, variant in (("base", args.base, "uniform"),
                                           ("new", args.new, "uniform"),
                                           ("base", args.base, "adaptive"),
                                           ("new", args.new, "adaptive")):
                keep = rnd == 0 and label == "new" and variant == "adaptive"
                run(label, binary, case, variant, directory, levels if keep else [])
    print(os.popen("uptime").read().strip())
    print("\n| case | levels | unknowns | estimate | true error | efficiency |")
    print("|---|---|---:|---:|---:|---:|")
    print("\n".join(levels))


if __name__ == "__main__":
    sys.exit(main())
