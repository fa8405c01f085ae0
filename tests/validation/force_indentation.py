#!/usr/bin/python3
"""Force-indentation curve F(delta) of the shipped Hertz half disk from one sweep, against
plane-strain (2D) Hertz theory: writes docs/figures/hertz_force_indentation.svg and prints the
table of docs/validation.md, "Force-indentation curve".

    /usr/bin/python3 tests/validation/force_indentation.py [--bin build/bin/fosls-contact]
        [--refinements 3] [--figure PATH] [--check TOL]

The case is solver/examples/hertz.json at rest (top fixed), the plane obstacle lifted by delta
(its "displacement"), the constraint along the obstacle normal, delta swept over ten values in
one `fosls-contact solve` (docs/case-format.md, "Sweeps"). For a cylinder of radius R pressed
by F per unit thickness, 2D Hertz gives a = sqrt(4FR/(pi E*)) and, against a far-field
reference, delta = F/(pi E*) (2 ln(4R/a) - 1). A finite body fixes the reference itself, so
the level of F/delta differs from the half-space formula; its growth with the load does not.
Needs python3-matplotlib (Debian's /usr/bin/python3).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DELTAS = [0.001 * k for k in range(1, 11)]


def sweep_case(refinements):
    with open(os.path.join(ROOT, "solver", "examples", "hertz.json")) as f:
        case = json.load(f)
    case["name"] = "hertz_indentation"
    case["mesh"]["refinements"] = refinements
    case["boundary"]["top"]["displacement"] = [0, 0]
    contact = case["boundary"]["contact"]
    contact["obstacle"]["displacement"] = [0, DELTAS[0]]
    contact["direction"] = "obstacle_normal"
    case["sweep"] = {"pointer": "/boundary/contact/obstacle/displacement/1", "values": DELTAS}
    return case


def solve(binary, case):
    with tempfile.TemporaryDirectory() as tmp:
        case_path = os.path.join(tmp, "case.json")
        out_path = os.path.join(tmp, "result.json")
        with open(case_path, "w") as f:
            json.dump(case, f)
        run = subprocess.run([binary, "solve", case_path, "--out", out_path],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if run.returncode != 0:
            sys.exit("%s solve failed (%d): %s" % (binary, run.returncode, run.stderr[-2000:]))
        with open(out_path) as f:
            return json.load(f)


def contact_modulus(material):
    mu, lam = material["mu"], material["lambda"]
    return 4 * mu if lam == "inf" else 4 * mu * (lam + mu) / (lam + 2 * mu)


def hertz_indentation(F, R, Estar):
    """delta(F) of a cylinder on a half-space, against a far-field reference."""
    a = math.sqrt(4 * F * R / (math.pi * Estar))
    return F / (math.pi * Estar) * (2 * math.log(4 * R / a) - 1)


def relative_stiffness_deviation(points, R, Estar):
    """Largest |FOSLS F/delta - Hertz F/delta|, both relative to their first point."""
    first = points[0]["force"][1] / points[0]["value"]
    first_hertz = points[0]["force"][1] / hertz_indentation(points[0]["force"][1], R, Estar)
    return max(abs(p["force"][1] / p["value"] / first -
                   p["force"][1] / hertz_indentation(p["force"][1], R, Estar) / first_hertz)
               for p in points)


def table(points, R, Estar):
    first = points[0]["force"][1] / points[0]["value"]
    first_hertz = points[0]["force"][1] / hertz_indentation(points[0]["force"][1], R, Estar)
    rows = ["| δ | F | F/δ | F/δ, relative | Hertz F/δ, relative | Hertz δ(F) | p_max | "
            "Hertz p0 | iterations |",
            "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for p in points:
        d, F = p["value"], p["force"][1]
        a = math.sqrt(4 * F * R / (math.pi * Estar))
        rows.append("| %.3g | %.5g | %.4g | %.4f | %.4f | %.4g | %.4g | %.4g | %d%s |" % (
            d, F, F / d, F / d / first, F / hertz_indentation(F, R, Estar) / first_hertz,
            hertz_indentation(F, R, Estar), p["peak_pressure"], 2 * F / (math.pi * a),
            p["iterations"], "" if p["converged"] else " (not converged)"))
    return "\n".join(rows)


def plot(points, R, Estar, path):
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "fosls"  # the same SVG for the same numbers
    import matplotlib.pyplot as plt

    delta = [p["value"] for p in points]
    force = [p["force"][1] for p in points]
    fine = [force[0] * 0.5 + (force[-1] * 1.05 - force[0] * 0.5) * k / 200 for k in range(201)]
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.5, 3.8))
    left.plot(delta, force, "o-", color="#1f5fbf", label="FOSLS sweep (one solve)")
    left.plot([hertz_indentation(F, R, Estar) for F in fine], fine, "--", color="#c0392b",
              label="2D Hertz, half-space reference")
    left.plot([0, delta[-1]], [0, force[0] / delta[0] * delta[-1]], ":", color="#777777",
              label="linear through the first point")
    left.set_xlabel("indentation δ (obstacle lift)")
    left.set_ylabel("contact force F (per unit thickness)")
    left.set_xlim(0, None)
    left.set_ylim(0, None)
    left.legend(fontsize=8, loc="upper left")
    left.grid(alpha=0.3)

    k0 = force[0] / delta[0]
    h0 = force[0] / hertz_indentation(force[0], R, Estar)
    right.plot(delta, [F / d / k0 for F, d in zip(force, delta)], "o-", color="#1f5fbf",
               label="FOSLS F/δ")
    right.plot(delta, [F / hertz_indentation(F, R, Estar) / h0 for F in force], "--",
               color="#c0392b", label="Hertz πE*/(2 ln(4R/a) − 1)")
    right.set_xlabel("indentation δ")
    right.set_ylabel("stiffness F/δ, relative to the first point")
    right.legend(fontsize=8, loc="upper left")
    right.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, format="svg", metadata={"Date": None})


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin", "fosls-contact"))
    parser.add_argument("--refinements", type=int, default=3)
    parser.add_argument("--figure",
                        default=os.path.join(ROOT, "docs", "figures", "hertz_force_indentation.svg"))
    parser.add_argument("--check", type=float, metavar="TOL",
                        help="fail unless every point converged, F grows with delta, and the "
                             "relative stiffness follows Hertz's within TOL")
    args = parser.parse_args()
    case = sweep_case(args.refinements)
    started = time.time()
    result = solve(args.bin, case)
    wall = time.time() - started
    points = result["sweep"]["points"]
    R = case["mesh"]["builtin"]["radius"]
    Estar = contact_modulus(result["material"])
    plot(points, R, Estar, args.figure)
    print("%d unknowns, E* = %.4g, R = %g, %d points in %.1f s (wall); wrote %s\n" % (
        result["dofs"], Estar, R, len(points), wall, os.path.relpath(args.figure, ROOT)))
    print(table(points, R, Estar))
    deviation = relative_stiffness_deviation(points, R, Estar)
    print("\nlargest deviation of the relative stiffness from Hertz's: %.4f" % deviation)
    if args.check is not None:
        forces = [p["force"][1] for p in points]
        problems = []
        if not all(p["converged"] for p in points):
            problems.append("a point did not converge")
        if any(b <= a for a, b in zip(forces, forces[1:])):
            problems.append("F does not grow with delta: %s" % forces)
        if not deviation <= args.check:
            problems.append("relative stiffness off Hertz's by %.4f > %g" % (deviation, args.check))
        # A linear F(delta) would keep the relative stiffness at 1: the check must see growth.
        growth = forces[-1] / points[-1]["value"] / (forces[0] / points[0]["value"])
        if not growth > 1.2:
            problems.append("stiffness grows by a factor %.3f only" % growth)
        if problems:
            sys.exit("force_indentation: " + "; ".join(problems))


if __name__ == "__main__":
    main()
