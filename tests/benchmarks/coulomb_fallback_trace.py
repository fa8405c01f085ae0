#!/usr/bin/env python3
"""Benchmark (not a test): what the iterations of Coulomb's fallback do (docs/method.md §8.4,
docs/performance.md "Friction"). One robustness case with Coulomb 𝔣 = 0.3, solved by mmg with
each FOSLS_CONTACT given in turn; per iteration from the switch on (friction.fallback_after),
each run's residual (after the switch pdas's: the kinked residual of the frozen bounds), its
active set's size and how many unknowns entered or left it, side by side.

usage: coulomb_fallback_trace.py CASE [VAR=VALUE,...@]FOSLS_CONTACT...
(a run's environment variables before an @)
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "robustness"))
sys.path.insert(0, os.path.join(HERE, "..", "validation"))
from coulomb_size_table import binary_and_environment  # noqa: E402
from robustness import load_case  # noqa: E402
import validation_lib as vl  # noqa: E402


def solve(run, case):
    binary, env = binary_and_environment(run)
    return vl.solve(binary, case, allow_unconverged=True, env=env)


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    case = load_case(sys.argv[1], 0.3)
    case.setdefault("solver", {})["method"] = "mmg"
    runs = [solve(b, case) for b in sys.argv[2:]]
    start = min((r["friction"]["fallback_after"] or 0) for r in runs)
    print("| iteration | " + " | ".join(f"run {i + 1}: residual, active, changed"
                                        for i in range(len(runs))) + " |")
    print("|---|" + "---|" * len(runs))
    for k in range(start, max(len(r["history"]) for r in runs)):
        cells = []
        for r in runs:
            h = r["history"][k] if k < len(r["history"]) else None
            cells.append(f"{h['kkt_residual']:.2e}, {h['active']}, {h['changed']}" if h else "")
        print(f"| {k} | " + " | ".join(cells) + " |")
    for i, r in enumerate(runs):
        f = r["friction"]
        print(f"run {i + 1}: {sys.argv[2 + i]}: {r['iterations']} iterations, switch after "
              f"{f['fallback_after']}, converged {r['converged']}, updates {f['updates']}, "
              f"changes {['%.1e' % c for c in f['update_changes']]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
