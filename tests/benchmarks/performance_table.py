#!/usr/bin/env python3
"""The performance table of docs/performance.md, from `fosls-contact bench --json`.

Runs the bench command on the curved-gap Signorini square with mmg and pdas, serial and on two
threads, each configuration in its own process (the bench command forks per row), and prints
a Markdown table: DOFs, iterations, setup/solve/total time, peak resident set, and the ratios
of mmg's time and memory to pdas's in the same run. With --busy a `yes > /dev/null` process
holds one core for the whole run (the behaviour when the machine is shared).

    tests/benchmarks/performance_table.py build/bin/fosls-contact --levels 4..8 [--busy]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("program")
    ap.add_argument("--levels", default="4..7")
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--methods", default="mmg,pdas")
    ap.add_argument("--busy", action="store_true", help="keep one core busy with `yes`")
    args = ap.parse_args()
    env = dict(os.environ)
    # Threads that wait sleep instead of spinning: a spinning waiter steals the core that a
    # busy machine has left (docs/performance.md).
    env.setdefault("OMP_WAIT_POLICY", "passive")
    busy = subprocess.Popen(["yes"], stdout=subprocess.DEVNULL) if args.busy else None
    try:
        with tempfile.NamedTemporaryFile(suffix=".json") as out:
            subprocess.run([args.program, "bench", "signorini_square", "--levels", args.levels,
                            "--methods", args.methods, "--threads", args.threads, "--json",
                            out.name], check=False, env=env, stdout=sys.stderr)
            rows = json.load(open(out.name))
    finally:
        if busy:
            busy.kill()
    print("| level | DOFs | method | threads | iterations | setup (s) | solve (s) | total (s) "
          "| peak (MiB) | time / pdas | memory / pdas |")
    print("|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        if "error" in r:
            print(f"| {r['level']} | – | {r['method']} | – | error: {r['error']} | | | | | | |")
            continue
        ratio = (f"{r['time_vs_pdas']:.2f} | {r['memory_vs_pdas']:.2f}"
                 if "time_vs_pdas" in r else "– | –")
        print(f"| {r['level']} | {r['dofs']:,} | {r['method']} | {r['threads']} | "
              f"{r['iterations']} | {r['setup_s']:.1f} | {r['solve_s']:.1f} | {r['total_s']:.1f} | "
              f"{r['peak_mib']:,.0f} | {ratio} |".replace(",", " "))


if __name__ == "__main__":
    main()
