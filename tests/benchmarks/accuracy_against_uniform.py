#!/usr/bin/env python3
"""hertz_3d_accuracy as shipped against the uniform route, hertz_3d_quarter at refinements 4,
side by side in one run (docs/performance.md, "3D: uniform against adaptive"; issue 48's time
target: the accuracy run in at most half the uniform route's time).

Each round runs, one after the other, one thread each (OMP_NUM_THREADS=1) under /usr/bin/time -v:
the quarter at r = 4 (with --after's program), then hertz_3d_accuracy with --before's program,
then with --after's. The machine is shared, so CPU time (user + system) is the comparison; wall
times and the steps' times (wall, from the result) are for the record.

    tests/benchmarks/accuracy_against_uniform.py --before OLD/bin/fosls-contact \\
        --after build/bin/fosls-contact [--rounds 2]

Errors against the ball's own force 0.0037014 (docs/validation.md §16); the quarter's forces
are a quarter of the half ball's, so 4 F_z is compared.
"""
import argparse
import json
import os
import re
import subprocess
import tempfile

BALL_FORCE = 0.0037014


def case(program, name, refinements=None):
    text = subprocess.run([program, "example", name], check=True, capture_output=True,
                          text=True).stdout
    data = json.loads(text)
    if refinements is not None:
        data["mesh"]["refinements"] = refinements
    return data


def timed_solve(program, data, work, label):
    path = os.path.join(work, label + ".json")
    out = os.path.join(work, label + ".result.json")
    with open(path, "w") as f:
        json.dump(data, f)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    run = subprocess.run(["/usr/bin/time", "-v", program, "solve", path, "--out", out, "-q"],
                         env=env, capture_output=True, text=True)

    def field(name):
        return re.search(re.escape(name) + r": (.*)", run.stderr).group(1).strip()

    wall = field("Elapsed (wall clock) time (h:mm:ss or m:ss)").split(":")
    with open(out) as f:
        result = json.load(f)
    return {
        "cpu": float(field("User time (seconds)")) + float(field("System time (seconds)")),
        "wall": sum(float(x) * 60**i for i, x in enumerate(reversed(wall))),
        "peak_gib": int(field("Maximum resident set size (kbytes)")) / 2**20,
        "exit": run.returncode,
        "result": result,
    }


def grouped(n):
    return f"{n:,}".replace(",", " ")


def summary(label, runs):
    r = runs[0]["result"]
    fz = 4 * r["contact"]["force"][2]
    steps = r.get("accuracy", {}).get("steps", [])
    cpu = ", ".join(f"{x['cpu']:.1f}" for x in runs)
    wall = ", ".join(f"{x['wall']:.0f}" for x in runs)
    peak = max(x["peak_gib"] for x in runs)
    levels = len(steps) if steps else r["mesh"].get("refinements", "")
    return (f"| {label} | {grouped(r['dofs'])} | {levels} | {cpu} | {wall} | {peak:.2f} GiB "
            f"| {fz:.7f} | {100 * (fz / BALL_FORCE - 1):+.2f} % |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--before", required=True)
    parser.add_argument("--after", required=True)
    parser.add_argument("--rounds", type=int, default=2)
    args = parser.parse_args()
    quarter = case(args.after, "hertz_3d_quarter", refinements=4)
    accuracy = case(args.after, "hertz_3d_accuracy")
    runs = {"quarter": [], "before": [], "after": []}
    with tempfile.TemporaryDirectory() as work:
        for k in range(args.rounds):
            runs["quarter"].append(timed_solve(args.after, quarter, work, f"quarter{k}"))
            runs["before"].append(timed_solve(args.before, accuracy, work, f"before{k}"))
            runs["after"].append(timed_solve(args.after, accuracy, work, f"after{k}"))
            print(f"round {k + 1}: " + ", ".join(f"{n} {v[-1]['cpu']:.1f} CPU s" for n, v in
                                                 runs.items()), flush=True)
    print("\n| run | unknowns | levels | CPU s (rounds) | wall s (rounds) | peak memory | 4 F_z "
          "| F_z error |")
    print("|---|---:|---:|---|---|---:|---:|---:|")
    print(summary("`hertz_3d_quarter`, r = 4", runs["quarter"]))
    print(summary("`hertz_3d_accuracy`, before", runs["before"]))
    print(summary("`hertz_3d_accuracy`, after", runs["after"]))
    q = sum(x["cpu"] for x in runs["quarter"]) / args.rounds
    for name in ("before", "after"):
        mean = sum(x["cpu"] for x in runs[name]) / args.rounds
        print(f"\n{name}: mean CPU {mean:.1f} s, {mean / q:.2f} of the quarter's {q:.1f} s")
    # Per step: unknowns, pdas iterations, the step's wall time (mean over the rounds).
    steps_before = [x["result"]["accuracy"]["steps"] for x in runs["before"]]
    steps_after = [x["result"]["accuracy"]["steps"] for x in runs["after"]]
    print("\n| step | unknowns | pdas it. before / after | step wall s before | after |")
    print("|---:|---:|---|---:|---:|")
    for i, (b, a) in enumerate(zip(steps_before[0], steps_after[0])):
        tb = sum(s[i]["time_s"] for s in steps_before) / len(steps_before)
        ta = sum(s[i]["time_s"] for s in steps_after) / len(steps_after)
        print(f"| {i} | {grouped(b['dofs'])} | {b['iterations']} / {a['iterations']} | "
              f"{tb:.1f} | {ta:.1f} |")
    fb = runs["before"][0]["result"]["contact"]["force"][2]
    fa = runs["after"][0]["result"]["contact"]["force"][2]
    print(f"\nF_z before {fb!r}, after {fa!r}: relative change {abs(fa - fb) / abs(fb):.1e}")


if __name__ == "__main__":
    main()
