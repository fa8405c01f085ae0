#!/usr/bin/env python3
"""Where the Cattaneo–Mindlin stick zone sits (docs/validation.md §13, "Where the stick zone sits").

The shipped cattaneo_mindlin (pressed, then shifted in two load steps) with the shift mirrored,
the indentation made four times smaller (the shifts with it, so Q/𝔣P stays near 0.16 and 0.31)
and the contact direction switched to obstacle_normal: per shift step, the offsets from the
pressure's centre x0 of the contact zone's centre and of the stick zone's (whole edges, and
with its fronts located within their edges), in units of the contact half-width a.

usage: stick_zone_position.py FOSLS_CONTACT [refinements ...]   (default 5; 6 takes minutes)
"""
import bisect
import math
import sys

from cattaneo_mindlin import F, loads, shipped, solve  # this directory's, as the script's own

VARIANTS = [  # (indentation, shift sign and scale, direction)
    (0.01, 1.0, "body_normal"), (0.01, -1.0, "body_normal"), (0.0025, 0.25, "body_normal"),
    (0.01, 1.0, "obstacle_normal"), (0.0025, 0.25, "obstacle_normal")]


def variant(binary, refinements, depth, shift, direction):
    """The shipped case with its indentation, shifts and contact direction changed."""
    c = shipped(binary, refinements)
    c["boundary"]["top"]["displacement"] = [0, -depth]
    c["boundary"]["contact"]["direction"] = direction
    c["load_steps"] = [{"/boundary/top/displacement/0": shift * k * 0.001} for k in (1, 2)]
    return c


def x_at(contact, s):
    """x of arc length s, linear between the edges' midpoints."""
    S, X = contact["s"], contact["x"]
    i = min(max(bisect.bisect_left(S, s), 1), len(S) - 1)
    return X[i - 1] + (X[i] - X[i - 1]) * (s - S[i - 1]) / (S[i] - S[i - 1])


def offsets(contact, radius):
    P, Q, a, x0 = loads(contact)
    zone, stick = contact["zone"], contact["stick_zone"]
    centre = lambda s0, s1: ((x_at(contact, s0) + x_at(contact, s1)) / 2 - x0) / a
    return {"a/R": a / radius, "Q/fP": Q / (F * P), "theory": math.sqrt(max(0.0, 1 - Q / (F * P))),
            "c/a": stick["length"] / 2 / a, "located c/a": stick["width"] / 2 / a,
            "zone": centre(zone["s_start"], zone["s_end"]),
            "stick": centre(stick["s_start"], stick["s_end"]),
            "located": centre(stick["front_start"], stick["front_end"]),
            "h/a": contact["length"][len(contact["length"]) // 2] / a}


def main():
    binary = sys.argv[1]
    levels = [int(v) for v in sys.argv[2:]] or [5]
    print("| refinements | direction | indentation | shift | a/R | h/a | Q/(𝔣P) | √(1 − Q/𝔣P) | "
          "c/a | located c/a | zone centre − x0 | stick centre − x0 | located − x0 |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in levels:
        for depth, shift, direction in VARIANTS:
            c = variant(binary, r, depth, shift, direction)
            result, radius = solve(binary, c), c["mesh"]["builtin"]["radius"]
            steps = result["load_steps"]["steps"]
            for k, step in enumerate(steps):
                if not step["contact"]["stick_zone"].get("edges"):
                    continue
                m = offsets(step["contact"], radius)
                print(f"| {r} | {direction} | {depth} | {shift * k * 0.001:+.4f} | {m['a/R']:.3f} | "
                      f"{m['h/a']:.4f} | {m['Q/fP']:.3f} | {m['theory']:.3f} | {m['c/a']:.3f} | "
                      f"{m['located c/a']:.3f} | {m['zone']:+.4f} | {m['stick']:+.4f} | "
                      f"{m['located']:+.4f} |", flush=True)


if __name__ == "__main__":
    main()
