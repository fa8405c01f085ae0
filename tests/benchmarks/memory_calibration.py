#!/usr/bin/env python3
"""Peak memory of a solve per method and size, and the coefficients of the job memory estimate.

Runs `fosls-contact solve` (the same library call a service job makes, VTU included) on the
shipped Signorini square at several refinement levels with each method, each in its own
process, and records the peak resident set (VmHWM) and the unknowns. It then fits
    peak_bytes ≈ base + per_unknown[method] · unknowns
by least squares on relative error and prints the table for docs/case-format.md and the
coefficients for solver/case/admission/resource_estimate.cpp.

    tests/benchmarks/memory_calibration.py build/bin/fosls-contact [--levels 4,5,6,7] [--hertz]
        [--adaptive] [--coulomb CASE.json...]

With --adaptive it also runs the shipped hertz_adaptive example to 6, 8 and 10 steps with mmg
and tnnmg (solved to the end: the adaptive mesh depends on the solutions) and prints the factor
by which its peak exceeds the uniform estimate for the same finest size: the
kAdaptiveHierarchyFactor of solver/case/admission/resource_estimate.hpp.

With --coulomb it measures instead what Coulomb's fallback to pdas costs (issue 49): each case
given (the robustness cases where mmg stalls, docs/validation.md §13) with Coulomb 𝔣 = 0.3 on
every contact group, solved to the end by mmg (which hands a stalled solve to pdas below
kFallbackMaxUnknowns) and by pdas, and frictionless by mmg, each peak against the estimate
`fosls-contact estimate` prints for the case: the fallback_bytes of
solver/case/admission/resource_estimate.hpp.

Only two iterations are run (not with --coulomb): the peak is reached while setting up (hierarchy, factorisation)
and in the first cycles; later iterations allocate nothing new.
"""
import argparse
import json
import subprocess
import sys
import tempfile
import time

METHODS = ["mmg", "tnnmg", "pdas", "pgs"]


def peak_of(cmd):
    """Runs cmd; returns (peak RSS in bytes, wall seconds, stdout)."""
    t0 = time.time()
    # Output goes to files, not pipes: the result JSON of a large case fills a pipe that is
    # only read at the end, and the child then blocks forever (seen at 2.1M unknowns).
    out_file = tempfile.TemporaryFile(mode="w+")
    err_file = tempfile.TemporaryFile(mode="w+")
    proc = subprocess.Popen(cmd, stdout=out_file, stderr=err_file, text=True)
    peak = 0
    status = f"/proc/{proc.pid}/status"
    while proc.poll() is None:
        try:
            with open(status) as f:
                for line in f:
                    if line.startswith("VmHWM:"):
                        peak = max(peak, int(line.split()[1]) * 1024)
        except OSError:
            pass
        time.sleep(0.02)
    proc.wait()
    out_file.seek(0)
    err_file.seek(0)
    out, err = out_file.read(), err_file.read()
    if proc.returncode not in (0, 3):
        sys.exit(f"{' '.join(cmd)} failed ({proc.returncode}): {err}")
    return peak, time.time() - t0, out


def least_squares(a, b):
    """Solves the normal equations aᵀa x = aᵀb (a few unknowns) by Gaussian elimination."""
    n = len(a[0])
    m = [[sum(r[i] * r[j] for r in a) for j in range(n)] + [sum(r[i] * bi for r, bi in zip(a, b))]
         for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(n):
            if r != c and m[c][c] != 0:
                f = m[r][c] / m[c][c]
                m[r] = [x - f * y for x, y in zip(m[r], m[c])]
    return [m[i][n] / m[i][i] for i in range(n)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cli")
    ap.add_argument("--levels", default="4,5,6,7")
    ap.add_argument("--hertz", action="store_true", help="also the Hertz example (graded gmsh mesh)")
    ap.add_argument("--adaptive", action="store_true", help="also the adaptive hierarchy factor")
    ap.add_argument("--coulomb", nargs="+", metavar="CASE",
                    help="only the price of Coulomb's fallback, on these cases")
    args = ap.parse_args()
    if args.coulomb:
        return coulomb_fallback(args.cli, args.coulomb)
    base_case = json.loads(subprocess.check_output([args.cli, "example", "signorini_square"]))
    rows = []
    cases = [("square", base_case, int(r)) for r in args.levels.split(",")]
    if args.hertz:
        hertz = json.loads(subprocess.check_output([args.cli, "example", "hertz"]))
        cases += [("hertz", hertz, r) for r in (3, 4, 5)]
    with tempfile.TemporaryDirectory() as tmp:
        for name, case, level in cases:
            for method in METHODS:
                c = json.loads(json.dumps(case))
                c["mesh"]["refinements"] = level
                c["solver"] = dict(c.get("solver", {}), method=method, max_iterations=2)
                path = f"{tmp}/case.json"
                with open(path, "w") as f:
                    json.dump(c, f)
                peak, wall, out = peak_of([args.cli, "solve", path, "--quiet", "--vtu", f"{tmp}/s.vtu"])
                dofs = json.loads(out)["dofs_total"]
                rows.append((name, level, method, dofs, peak, wall))
                print(f"{name:7s} r={level} {method:6s} unknowns {dofs:9d} peak {peak / 2**20:8.1f} MiB"
                      f"  {wall:6.1f} s", file=sys.stderr, flush=True)
    # Fit: one common base, one slope per method, least squares on relative error.
    fit_rows = [r for r in rows if r[0] == "square"]
    n = 1 + len(METHODS)
    design = []
    for _, _, method, dofs, peak, _ in fit_rows:
        row = [0.0] * n
        row[0] = 1.0 / peak
        row[1 + METHODS.index(method)] = dofs / peak
        design.append(row)
    coef = least_squares(design, [1.0] * len(design))
    base, slopes = coef[0], dict(zip(METHODS, coef[1:]))
    print(f"base {base / 2**20:.1f} MiB; bytes per unknown: " +
          ", ".join(f"{m} {slopes[m]:.0f}" for m in METHODS))
    print("\n| case | level | method | unknowns | peak (MiB) | estimate (MiB) | error |")
    print("|---|---|---|---|---|---|---|")
    for name, level, method, dofs, peak, _ in rows:
        est = base + slopes[method] * dofs
        print(f"| {name} | {level} | {method} | {dofs} | {peak / 2**20:.0f} | {est / 2**20:.0f} | "
              f"{100 * (est - peak) / peak:+.0f} % |")
    if args.adaptive:
        adaptive_factor(args.cli, base, slopes)


def adaptive_factor(cli, base, slopes):
    """Peak of adaptive runs against the uniform estimate base + slope · unknowns."""
    case = json.loads(subprocess.check_output([cli, "example", "hertz_adaptive"]))
    print("\n| adaptive steps | method | finest unknowns | levels | peak (MiB) | "
          "uniform estimate (MiB) | factor |")
    print("|---|---|---|---|---|---|---|")
    factors = []
    with tempfile.TemporaryDirectory() as tmp:
        for steps in (6, 8, 10):
            for method in ("mmg", "tnnmg"):
                c = json.loads(json.dumps(case))
                c["adaptivity"] = dict(c["adaptivity"], steps=steps, max_dofs=1000000)
                c["solver"] = dict(c.get("solver", {}), method=method)
                path = f"{tmp}/case.json"
                with open(path, "w") as f:
                    json.dump(c, f)
                peak, _, out = peak_of([cli, "solve", path, "--quiet", "--vtu", f"{tmp}/s.vtu"])
                result = json.loads(out)
                dofs = result["dofs_total"]
                uniform = base + slopes[method] * dofs
                factor = (peak - base) / (slopes[method] * dofs)
                factors.append(factor)
                print(f"| {steps} | {method} | {dofs} | {result['levels']} | {peak / 2**20:.0f} | "
                      f"{uniform / 2**20:.0f} | {factor:.2f} |", flush=True)
    print(f"largest factor {max(factors):.2f}")


def with_friction(case, coefficient, method):
    c = json.loads(json.dumps(case))
    c["solver"] = dict(c.get("solver", {}), method=method)
    for condition in c["boundary"].values():
        if condition.get("type") == "contact":
            condition.pop("friction", None)
            if coefficient:
                condition["friction"] = {"coefficient": coefficient}
    return c


def estimated_mib(cli, path, method):
    """The memory `fosls-contact estimate` prints for `method` (its table of methods)."""
    for line in subprocess.check_output([cli, "estimate", path], text=True).splitlines():
        words = line.split()
        if len(words) >= 3 and words[0] == method and words[2] == "MiB":
            return float(words[1])
    return float("nan")


def coulomb_fallback(cli, paths):
    """Peaks of Coulomb by mmg (with its fallback) and by pdas, and of frictionless mmg."""
    print("| case | unknowns | run | where pdas took over | peak (MiB) | estimate (MiB) |")
    print("|---|---|---|---|---|---|")
    runs = [("frictionless, mmg", 0.0, "mmg"), ("Coulomb 0.3, mmg", 0.3, "mmg"),
            ("Coulomb 0.3, pdas", 0.3, "pdas")]
    with tempfile.TemporaryDirectory() as tmp:
        for path in paths:
            with open(path) as f:
                case = json.load(f)
            for label, coefficient, method in runs:
                c = with_friction(case, coefficient, method)
                case_path = f"{tmp}/case.json"
                with open(case_path, "w") as f:
                    json.dump(c, f)
                peak, _, out = peak_of([cli, "solve", case_path, "--quiet", "--vtu", f"{tmp}/s.vtu"])
                result = json.loads(out)
                switched = (result.get("friction") or {}).get("fallback_after")
                print(f"| {c.get('name', path)} | {result['dofs_total']} | {label} | "
                      f"{switched if switched else '—'} | {peak / 2**20:.0f} | "
                      f"{estimated_mib(cli, case_path, method):.0f} |", flush=True)
    return 0


if __name__ == "__main__":
    main()
