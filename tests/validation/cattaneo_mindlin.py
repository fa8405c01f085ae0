#!/usr/bin/env python3
"""Cattaneo–Mindlin check of Coulomb friction (docs/validation.md, "Cattaneo–Mindlin").

The incompressible half disk of hertz_incompressible pressed onto the rigid plane and moved
sideways: with ν = 0.5 against a rigid body Dundurs' β = 0, the normal problem does not feel
the tangential one, so pressing and shifting in one step gives the same slip as pressing first
and shifting after. Per refinement: the stick-zone half-width c/a against √(1 − Q/(𝔣P)) and
the relative L2 error of the shear traction against 𝔣p₀(√(1 − x²/a²) − (c/a)√(1 − x²/c²)) over
the contact zone (the second term only inside the stick zone), with the computed P, Q, a.

With --load-steps the shipped example cattaneo_mindlin is solved as it is shipped: pressed in
step 0, then shifted by 0.001 and 0.002 in steps 1 and 2, each from the previous step's solution
(the slip measured from it); its shift steps are compared.

The stick zone is the result's (edges whose vertices did not slip in the step, docs/result-format.md);
"located" is the same zone with its fronts located within their edges (contact.stick_zone.width,
docs/method.md §8.3); the last column reads it as before issue 49, from |σ_nt| below the bound 𝔣p.

usage: cattaneo_mindlin.py FOSLS_CONTACT [--load-steps] [--save DIR | --load DIR] [refinements ...]
(with --load-steps, --save DIR keeps each result as DIR/cattaneo_mindlin_rN_stepped.json, for the
figure, tests/validation/cattaneo_mindlin_figure.py; --load DIR reads them instead of solving).
"fronts beyond" says where each end of the stick zone's fronts lies beyond the whole-edge
zone, in edge lengths, start; end: the theory's ±c, then the located front.
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

F = 0.3


def case(binary, refinements, shift):
    c = json.loads(subprocess.run([binary, "example", "hertz_incompressible"],
                                  capture_output=True, text=True, check=True).stdout)
    c["name"] = "cattaneo_mindlin"
    c["mesh"]["refinements"] = refinements
    c["boundary"]["top"]["displacement"] = [shift, -0.01]
    c["boundary"]["contact"]["friction"] = {"coefficient": F}
    return c


def solve(binary, c, keep=None):
    with tempfile.TemporaryDirectory() as d:
        path, out = d + "/case.json", d + "/result.json"
        json.dump(c, open(path, "w"))
        subprocess.run([binary, "solve", path, "--out", out], capture_output=True)
        if keep:
            shutil.copyfile(out, keep)
        return json.load(open(out))


def shipped(binary, refinements):
    c = json.loads(subprocess.run([binary, "example", "cattaneo_mindlin"],
                                  capture_output=True, text=True, check=True).stdout)
    c["mesh"]["refinements"] = refinements
    return c


def stepped(result):
    """The shift steps of a load-stepped result as (shift, step result) pairs."""
    return [(0.001 * k, s) for k, s in enumerate(result["load_steps"]["steps"]) if k > 0]


def loads(c):
    """A result's contact: the normal load P, the tangential load |Q|, the half-width a and the
    pressure's centre x0."""
    P = sum(p * l for p, l in zip(c["pressure"], c["length"]))
    Q = abs(sum(s * l for s, l in zip(c["shear"], c["length"])))
    x0 = sum(x * p * l for x, p, l in zip(c["x"], c["pressure"], c["length"])) / P
    return P, Q, c["zone"]["width"] / 2, x0


def compare(r):
    c = r["contact"]
    P, Q, a, x0 = loads(c)
    p0 = 2 * P / (math.pi * a)
    ratio = math.sqrt(max(0.0, 1 - Q / (F * P)))
    stick = c["stick_zone"]["length"] / 2 / a
    located = c["stick_zone"].get("width", float("nan")) / 2 / a
    # The state as it was read before issue 49: stick where |σ_nt| is below the bound 𝔣p (to
    # 1e-4 of the largest bound: the bound is that of the last update, 𝔣p the final iterate's).
    largest = F * max(c["pressure"])
    below = [l for s, p, l, on in zip(c["shear"], c["pressure"], c["length"], c["active"])
             if on and abs(s) < F * p - 1e-4 * largest]
    stick_by_traction = sum(below) / 2 / a
    zone = c["stick_zone"]
    first = c["state"].index("stick")
    last = len(c["state"]) - 1 - c["state"][::-1].index("stick")
    h = c["length"][first]
    ends = (c["x"][first] - c["length"][first] / 2 - x0, c["x"][last] + c["length"][last] / 2 - x0)
    beyond = ((ends[0] + ratio * a) / h, (ratio * a - ends[1]) / h,
              (zone["s_start"] - zone.get("front_start", zone["s_start"])) / h,
              (zone.get("front_end", zone["s_end"]) - zone["s_end"]) / h)
    num = den = 0.0
    for x, s, l, active in zip(c["x"], c["shear"], c["length"], c["active"]):
        xi = (x - x0) / a
        if abs(xi) >= 1:
            continue
        ref = F * p0 * math.sqrt(1 - xi * xi)
        if abs(xi) < ratio:
            ref -= F * p0 * ratio * math.sqrt(1 - (xi / ratio) ** 2)
        num += (abs(s) - ref) ** 2 * l
        den += ref * ref * l
    return {"Q/fP": Q / (F * P), "c/a": stick, "theory c/a": ratio, "located c/a": located,
            "c/a by traction": stick_by_traction, "beyond": beyond,
            "shear L2": math.sqrt(num / den) if den else float("nan"),
            "edges in zone": c["zone"]["edges"], "iterations": r["iterations"],
            "stick edges": c["stick_zone"]["edges"],
            "slip below bound": c["stick_zone"].get("slipping_below_bound", "—"),
            "updates": r.get("friction", {}).get("updates")}


def main():
    binary = sys.argv[1]
    args = sys.argv[2:]
    load_steps = "--load-steps" in args
    save = args[args.index("--save") + 1] if "--save" in args else None
    load = args[args.index("--load") + 1] if "--load" in args else None
    levels = [int(v) for v in args if v.isdigit()] or [3, 4, 5]
    print("| refinements | shift | edges in zone | Q/(𝔣P) | √(1 − Q/𝔣P) | c/a whole edges | "
          "difference | c/a located | difference | shear rel. L2 | mmg iterations | updates | "
          "fronts beyond: theory; located (edges) | "
          "stick edges | slipping below bound | c/a by traction |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in levels:
        if load_steps:
            name = f"cattaneo_mindlin_r{r}_stepped.json"
            if load:
                runs = stepped(json.load(open(os.path.join(load, name))))
            else:
                runs = stepped(solve(binary, shipped(binary, r), save and os.path.join(save, name)))
        else:
            runs = [(shift, solve(binary, case(binary, r, shift))) for shift in (0.001, 0.002)]
        for shift, result in runs:
            m = compare(result)
            b = m["beyond"]
            print(f"| {r} | {shift} | {m['edges in zone']} | {m['Q/fP']:.3f} | "
                  f"{m['theory c/a']:.3f} | {m['c/a']:.3f} | {m['c/a'] - m['theory c/a']:+.3f} | "
                  f"{m['located c/a']:.3f} | {m['located c/a'] - m['theory c/a']:+.3f} | "
                  f"{m['shear L2']:.3f} | {m['iterations']} | "
                  f"{m['updates']} | {b[0]:.2f}, {b[1]:.2f}; {b[2]:.2f}, {b[3]:.2f} | "
                  f"{m['stick edges']} | {m['slip below bound']} | "
                  f"{m['c/a by traction']:.3f} |", flush=True)


if __name__ == "__main__":
    main()
