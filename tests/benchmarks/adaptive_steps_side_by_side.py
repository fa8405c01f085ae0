#!/usr/bin/env python3
"""adaptive_steps_side_by_side.py BASE_BIN [NEW_BIN ...] [--rounds N] [--dir DIR] [--cases c,...]
                                   [--tols t,...] [--uniform-once] [--c2-volumetric W]

The tables of docs/performance.md "The accuracy loop's solver levels a uniform factor apart" and
"A last step sized to the tolerance": the 2D Hertz cases and the Signorini squares (lambda = 1
and inf) to a force accuracy of 5e-4 (or --tols) from refinements 2 with mmg, uniform and
adaptive levels with BASE_BIN and NEW_BIN (--uniform-once: uniform levels with BASE_BIN only,
for a change that leaves them alone; several NEW_BINs, e.g. scripts that set a variant's
environment, are labelled by their file names; none: BASE_BIN's levels only), optionally with
weights.c2_volumetric W, alternately in one script (one thread, /usr/bin/time -v:
CPU time = user + sys, peak resident set). The true error is against the references of
docs/validation.md sections 12 and 14. Then, per level of both binaries' adaptive runs (first
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

REFERENCE = {"hertz": 0.0125226, "hertz_incompressible": 0.0214937, "signorini_square": 0.083366,
             "signorini_square_incompressible": 0.136701}
# name: the accuracy section's levels (the force tolerance is added)
VARIANTS = {"uniform": {"refinement": "uniform"}, "adaptive": {"refinement": "adaptive"}}


def case_file(binary, case, variant, directory, label, tol, c2_volumetric):
    d = json.loads(subprocess.run([binary, "example", case], check=True, capture_output=True,
                                  text=True).stdout)
    d["mesh"]["refinements"] = 2
    d["accuracy"] = {"force": tol, **VARIANTS[variant]}
    d["solver"] = {"method": "mmg"}
    if c2_volumetric:
        d["weights"] = {**d.get("weights", {}), "c2_volumetric": c2_volumetric}
    path = os.path.join(directory, f"{case}_{tol}_{variant}_{label}.json")
    with open(path, "w") as f:
        json.dump(d, f)
    return path


def run(label, binary, case, variant, directory, levels_out, tol, c2_volumetric=None):
    path = case_file(binary, case, variant, directory, label, tol, c2_volumetric)
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
    force = abs(r["contact"]["force"][1])  # the obstacles' normal is y
    true_error = abs(force - ref) / ref
    steps = a["steps"]
    print(f"| {case} | {tol} | {variant}, {label} | {cpu:.2f} | {wall} | {rss / 1024:.0f} | {len(steps)} | "
          f"{r['dofs']} | {a['reached']} | {fmt(a['estimate'])} | {100 * true_error:.4f} % | "
          f"{', '.join(str(s['iterations']) for s in steps)} |", flush=True)
    for s in steps:
        e = abs(abs(s["force"][1]) - ref) / ref
        est = s["estimate"]
        levels_out.append(f"| {case} | {tol} | {variant}, {label} | {s['dofs']} | {fmt(est)} | {100 * e:.4f} % | "
                          f"{'—' if est is None else f'{est / e:.2f}'} |")


def fmt(x):
    return "—" if x is None else f"{100 * x:.4f} %"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("base")
    p.add_argument("new", nargs="*")
    p.add_argument("--rounds", type=int, default=2)
    p.add_argument("--dir", default=None)
    p.add_argument("--cases", default="hertz,hertz_incompressible")
    p.add_argument("--tols", default="5e-4")
    p.add_argument("--uniform-once", action="store_true")
    p.add_argument("--c2-volumetric", type=float, default=None)
    args = p.parse_args()
    directory = args.dir or tempfile.mkdtemp()
    os.makedirs(directory, exist_ok=True)
    print(os.popen("uptime").read().strip())
    print("| case | tol | levels | CPU s | wall | peak MiB | solves | last unknowns | reached | estimate | "
          "true error | iterations per solve |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---|---:|---:|---|")
    levels = []
    news = [("new" if len(args.new) == 1 else os.path.splitext(os.path.basename(b))[0], b)
            for b in args.new]
    for rnd in range(args.rounds):
        for case in args.cases.split(","):
            for tol in (float(t) for t in args.tols.split(",")):
                runs = [("base", args.base, "uniform")]
                if not args.uniform_once:
                    runs += [(label, b, "uniform") for label, b in news]
                runs += [("base", args.base, "adaptive")]
                runs += [(label, b, "adaptive") for label, b in news]
                for label, binary, variant in runs:
                    keep = rnd == 0 and variant == "adaptive"
                    run(label, binary, case, variant, directory, levels if keep else [], tol,
                        args.c2_volumetric)
    print(os.popen("uptime").read().strip())
    print("\n| case | tol | levels | unknowns | estimate | true error | efficiency |")
    print("|---|---:|---|---:|---:|---:|---:|")
    print("\n".join(levels))


if __name__ == "__main__":
    sys.exit(main())
