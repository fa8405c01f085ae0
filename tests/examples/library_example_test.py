#!/usr/bin/env python3
"""examples/library_example against `fosls-contact solve` on the same cases.

    library_example_test.py LIBRARY_EXAMPLE FOSLS_CONTACT CASE.json...

The example prints `force: F_x F_y` (17 significant digits) and `iterations: N`; the CLI's
result JSON has contact.force and iterations. They must be equal exactly: the example runs the
library's public entry point (read_case, run_case) as the CLI does, so any difference is a
difference between the two paths through the library.
"""
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path


def example_output(program, case):
    r = subprocess.run([program, case], capture_output=True, text=True, timeout=240)
    if r.returncode != 0:
        sys.exit(f"{program} {case}: exit {r.returncode}\n{r.stdout}{r.stderr}")
    force = re.search(r"^force:\s+(\S+) (\S+)$", r.stdout, re.M)
    iterations = re.search(r"^iterations:\s+(\d+)$", r.stdout, re.M)
    if not force or not iterations:
        sys.exit(f"{program} {case}: no force or iterations line in\n{r.stdout}")
    return [float(force.group(1)), float(force.group(2))], int(iterations.group(1))


def cli_output(program, case):
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "result.json"
        r = subprocess.run([program, "solve", case, "--out", str(out), "--quiet"],
                           capture_output=True, text=True, timeout=240)
        if r.returncode != 0:
            sys.exit(f"{program} solve {case}: exit {r.returncode}\n{r.stderr}")
        result = json.loads(out.read_text())
    return [float(f) for f in result["contact"]["force"]], int(result["iterations"])


def main():
    example, cli, cases = sys.argv[1], sys.argv[2], sys.argv[3:]
    if not cases:
        sys.exit("no cases given")
    failed = False
    for case in cases:
        ex_force, ex_iterations = example_output(example, case)
        cli_force, cli_iterations = cli_output(cli, case)
        same = ex_force == cli_force and ex_iterations == cli_iterations
        print(f"{Path(case).name}: example F = {ex_force!r}, {ex_iterations} iterations; "
              f"fosls-contact F = {cli_force!r}, {cli_iterations} iterations: "
              f"{'equal' if same else 'DIFFERENT'}")
        if ex_force == [0.0, 0.0]:
            print(f"{Path(case).name}: the force is zero: the case tests nothing")
            failed = True
        failed |= not same
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
