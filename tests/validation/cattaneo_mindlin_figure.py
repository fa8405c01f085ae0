#!/usr/bin/python3
"""The figure of docs/validation.md §13: the shipped cattaneo_mindlin with load steps (pressed,
then shifted by 0.001 and 0.002), each shift step's shear traction |σ_nt| and slip bound fp
against Cattaneo–Mindlin's profile for the computed P, Q and contact width, with the stick zone
of whole edges shaded, its fronts located within their edges (contact.stick_zone.front_start,
front_end; docs/method.md §8.3) and the theory's ±c marked.

    /usr/bin/python3 tests/validation/cattaneo_mindlin_figure.py [--bin build/bin/fosls-contact]
        [--refinements 6] [--result SAVED.json] [--figure PATH]

--result reads a result saved by `cattaneo_mindlin.py --load-steps --save DIR` instead of
solving. Needs python3-matplotlib (Debian's /usr/bin/python3).
"""
import argparse
import json
import math
import os
import subprocess
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def solve(binary, refinements):
    case = json.loads(subprocess.run([binary, "example", "cattaneo_mindlin"], capture_output=True,
                                     text=True, check=True).stdout)
    case["mesh"]["refinements"] = refinements
    with tempfile.TemporaryDirectory() as tmp:
        path, out = os.path.join(tmp, "case.json"), os.path.join(tmp, "result.json")
        with open(path, "w") as f:
            json.dump(case, f)
        subprocess.run([binary, "solve", path, "--out", out], capture_output=True, check=False)
        with open(out) as f:
            return json.load(f)


def coefficient(result):
    laws = result["friction"]["groups"]
    return next(iter(laws.values()))["coefficient"]


def profile(contact, f):
    """What the panel draws, in x/a from the pressure's centre and traction over fp₀."""
    lengths, pressure, shear, xs = (contact[k] for k in ("length", "pressure", "shear", "x"))
    P = sum(p * l for p, l in zip(pressure, lengths))
    Q = abs(sum(s * l for s, l in zip(shear, lengths)))
    a = contact["zone"]["width"] / 2
    x0 = sum(x * p * l for x, p, l in zip(xs, pressure, lengths)) / P
    p0 = 2 * P / (math.pi * a)
    ratio = math.sqrt(max(0.0, 1 - Q / (f * P)))
    ss = contact["s"]

    def x_of_s(s):  # the boundary's x at arc length s, between the edges' midpoints
        import numpy as np
        return (np.interp(s, ss, xs) - x0) / a

    zone = contact["stick_zone"]
    return {"a": a, "p0": p0, "ratio": ratio, "Q/fP": Q / (f * P), "x0": x0,
            "edges": [((x - l / 2 - x0) / a, (x + l / 2 - x0) / a, abs(s) / (f * p0),
                       p / p0) for x, l, s, p in zip(xs, lengths, shear, pressure)],
            "whole": (x_of_s(zone["s_start"]), x_of_s(zone["s_end"])),
            "located": (x_of_s(zone["front_start"]), x_of_s(zone["front_end"])),
            "stick edges": zone["edges"]}


def panel(ax, m, shift):
    import numpy as np
    xs, shear, bound = [], [], []
    for lo, hi, s, p in m["edges"]:
        xs += [lo, hi]
        shear += [s, s]
        bound += [p, p]
    c = m["ratio"]
    x = np.linspace(-1.15, 1.15, 1201)
    outer = np.sqrt(np.clip(1 - x * x, 0, None))
    inner = np.where(np.abs(x) < c, c * np.sqrt(np.clip(1 - (x / c) ** 2, 0, None)), 0.0)
    ax.axvspan(*m["whole"], color="#9ecae1", alpha=0.35,
               label="stick zone, whole edges (%d)" % m["stick edges"])
    ax.plot(xs, bound, color="#999999", lw=1.0, label="slip bound fp (computed)")
    ax.plot(x, outer, ":", color="#555555", lw=1.0, label="fp₀√(1 − x²/a²)")
    ax.plot(xs, shear, color="#1f5fbf", lw=1.3, label="|σ_nt| (computed, per edge)")
    ax.plot(x, outer - inner, "--", color="#c0392b", lw=1.3,
            label="Cattaneo–Mindlin, c/a = %.3f" % c)
    for k, front in enumerate(m["located"]):
        ax.axvline(front, color="#2ca02c", lw=1.4,
                   label="located fronts, c/a = %.3f" % ((m["located"][1] - m["located"][0]) / 2)
                   if k == 0 else None)
    for k, front in enumerate((-c, c)):
        ax.axvline(front, color="#c0392b", lw=0.8, ls="--")
    ax.set_xlim(-1.15, 1.15)
    ax.set_ylim(0, 1.12)
    ax.set_xlabel("x / a (from the pressure's centre)")
    ax.set_ylabel("traction / fp₀")
    ax.set_title("shift %g: Q/fP = %.3f" % (shift, m["Q/fP"]), fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="center")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin", "fosls-contact"))
    parser.add_argument("--refinements", type=int, default=6)
    parser.add_argument("--result", help="a saved result of the shipped example with load steps")
    parser.add_argument("--figure",
                        default=os.path.join(ROOT, "docs", "figures", "cattaneo_mindlin.svg"))
    args = parser.parse_args()
    if args.result:
        with open(args.result) as f:
            result = json.load(f)
    else:
        result = solve(args.bin, args.refinements)
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "fosls"  # the same SVG for the same numbers
    import matplotlib.pyplot as plt

    f = coefficient(result)
    steps = result["load_steps"]["steps"][1:]
    fig, axes = plt.subplots(1, len(steps), figsize=(5.2 * len(steps), 4.2))
    for k, (ax, step) in enumerate(zip(axes, steps)):
        m = profile(step["contact"], f)
        panel(ax, m, 0.001 * (k + 1))
        print("shift %g: a = %.5f, Q/fP = %.3f, c/a theory %.3f, whole edges %.3f, located %.3f"
              % (0.001 * (k + 1), m["a"], m["Q/fP"], m["ratio"],
                 (m["whole"][1] - m["whole"][0]) / 2, (m["located"][1] - m["located"][0]) / 2))
    fig.suptitle("cattaneo_mindlin with load steps, refinements %d (%d unknowns), f = %g"
                 % (result["mesh"]["refinements"], result["dofs"], f), fontsize=10)
    fig.tight_layout()
    svg = args.figure.endswith(".svg")
    fig.savefig(args.figure, **({"format": "svg", "metadata": {"Date": None}} if svg else {}))
    print("wrote", os.path.relpath(args.figure, ROOT))


if __name__ == "__main__":
    main()
