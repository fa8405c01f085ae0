#!/usr/bin/env python3
"""The figure of an adapted half ball (docs/figures/hertz_3d_adapted.svg, validation.md §16).

Solves the shipped hertz_3d_accuracy (the quarter ball, refined adaptively to 1 %) with the given
fosls-contact, writes its VTU as ASCII, and draws two panels as SVG, in pure Python:
  left:  the contact side seen from below (the boundary faces facing down, projected onto the
         x-y plane, 0 <= x, y <= 0.15), coloured by the contact pressure, with Hertz's radius
         for the ball's force dashed: the bisection refinement gathers at the contact front;
  right: the symmetry plane y = 0 (the boundary faces there, in x-z): the refinement through
         the body, towards the contact zone and the clamped rim.
Usage: adapted_ball_figure.py BUILD_DIR [OUT.svg]
"""
import json
import os
import re
import subprocess
import sys
import tempfile

def arrays(vtu):
    text = open(vtu).read()
    out = {}
    for m in re.finditer(r'<DataArray[^>]*Name="([^"]+)"[^>]*>([^<]*)</DataArray>', text):
        out.setdefault(m.group(1), [float(x) for x in m.group(2).split()])
    pts = re.search(r'<Points>\s*<DataArray[^>]*>([^<]*)</DataArray>', text).group(1).split()
    out["points"] = [float(x) for x in pts]
    return out

def boundary_faces(conn):
    seen = {}
    for t in range(0, len(conn), 4):
        tet = [int(v) for v in conn[t:t + 4]]
        for drop in range(4):
            face = tuple(sorted(tet[:drop] + tet[drop + 1:]))
            seen[face] = seen.get(face, 0) + 1
    return [f for f, n in seen.items() if n == 1]

def colour(v, top):
    s = max(0.0, min(1.0, v / top)) if top > 0 else 0.0
    # light grey (no pressure) to dark red
    r, g, b = 235 - int(60 * s), 235 - int(205 * s), 235 - int(205 * s)
    return f"rgb({r},{g},{b})"

def panel(faces, xy, fill, box, origin, size, clip):
    (x0, x1), (y0, y1) = box
    scale = size / max(x1 - x0, y1 - y0)
    out = [f'<clipPath id="{clip}"><rect x="{origin[0]}" y="{origin[1]}" width="{size}" height="{size}"/></clipPath>',
           f'<g clip-path="url(#{clip})">']
    for f, c in zip(faces, fill):
        pts = " ".join(f"{origin[0] + (xy[v][0] - x0) * scale:.2f},{origin[1] + (y1 - xy[v][1]) * scale:.2f}" for v in f)
        out.append(f'<polygon points="{pts}" fill="{c}" stroke="#333" stroke-width="0.3"/>')
    out.append("</g>")
    return out

def main():
    build = sys.argv[1]
    target = sys.argv[2] if len(sys.argv) > 2 else "docs/figures/hertz_3d_adapted.svg"
    here = os.path.dirname(os.path.abspath(__file__))
    case = os.path.join(here, "..", "..", "solver", "examples", "3d", "hertz_3d_accuracy.json")
    with tempfile.TemporaryDirectory() as tmp:
        vtu, res = os.path.join(tmp, "s.vtu"), os.path.join(tmp, "r.json")
        subprocess.run([os.path.join(build, "bin", "fosls-contact"), "solve", case, "-q", "-o", res,
                        "--vtu", vtu, "--vtu-format", "ascii"], check=True)
        a = arrays(vtu)
        result = json.load(open(res))
    p = a["points"]
    x = [(p[i], p[i + 1], p[i + 2]) for i in range(0, len(p), 3)]
    pressure = a["contact_pressure"]
    faces = boundary_faces(a["connectivity"])
    below, below_fill, side, side_fill = [], [], [], []
    top = max(pressure)
    for f in faces:
        if all(abs(x[v][1]) < 1e-12 for v in f):
            side.append(f)
            side_fill.append("rgb(225,232,240)")
        elif all(x[v][2] < -0.95 for v in f) and min(x[v][0] for v in f) < 0.15 and min(x[v][1] for v in f) < 0.15:
            below.append(f)
            below_fill.append(colour(sum(pressure[v] for v in f) / 3, top))
    size = 380
    left = panel(below, [(v[0], v[1]) for v in x], below_fill, ((0, 0.15), (0, 0.15)), (20, 40), size, "below")
    right = panel(side, [(v[0], v[2]) for v in x], side_fill, ((0, 1.0), (-1.0, 0.0)), (440, 40), size, "side")
    zone = result["contact"]["zone"]
    force = 2 ** zone["symmetry_planes"] * result["contact"]["force"][2]
    hertz_a = (3 * force / (4 * 8 / 3)) ** (1 / 3)  # R = 1, E* = 8/3 (mu = lambda = 1)
    scale = size / 0.15
    arc = (f'<path d="M {20 + hertz_a * scale:.1f} {40 + size} A {hertz_a * scale:.1f} {hertz_a * scale:.1f} 0 0 0 '
           f'20 {40 + size - hertz_a * scale:.1f}" fill="none" stroke="black" stroke-width="1.5" stroke-dasharray="6 4"/>')
    loop = result.get("accuracy") or result.get("adaptivity")
    title = (f"hertz_3d_accuracy: {result['dofs']} unknowns, {result['tetrahedra']} tetrahedra after "
             f"{len(loop['steps']) - 1} steps; contact radius {zone['radius']:.4f}")
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="840" height="450" font-family="sans-serif" font-size="13">',
           '<rect width="100%" height="100%" fill="white"/>',
           f'<text x="20" y="22">{title}</text>', *left, arc, *right,
           '<text x="20" y="440">from below, 0 ≤ x, y ≤ 0.15: pressure; dashed: Hertz a</text>',
           '<text x="440" y="440">symmetry plane y = 0, 0 ≤ x ≤ 1, −1 ≤ z ≤ 0</text>', "</svg>"]
    open(target, "w").write("\n".join(svg) + "\n")
    print(f"{target}: {len(below)} faces below, {len(side)} on the symmetry plane")

if __name__ == "__main__":
    main()
