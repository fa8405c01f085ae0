"""Shared pieces of the validation: running fosls-contact on a case, the plane-strain Hertz
reference (docs/method.md §6) and the measures compared with it.

Standard library only, so that the regression tests (test_validation.py) run without numpy or
matplotlib; run_validation.py adds the tables and figures on top.
"""

import copy
import json
import math
import os
import re
import subprocess
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLES = os.path.join(ROOT, "solver", "examples")


def load_example(name):
    """The shipped case solver/examples/NAME.json as a dict."""
    with open(os.path.join(EXAMPLES, name + ".json")) as f:
        return json.load(f)


class SolveError(RuntimeError):
    """fosls-contact failed (exit code other than 0 = converged and 3 = not converged)."""


def solve(binary, case, vtu=False, allow_unconverged=False, env=None):
    """Runs `fosls-contact solve` on a case dict (in the environment `env`, the caller's if
    None); returns the result JSON as a dict, and with vtu=True also the solution as parsed by
    read_vtu under the key "vtu"."""
    with tempfile.TemporaryDirectory(prefix="fosls-validation-") as tmp:
        case_path = os.path.join(tmp, "case.json")
        out_path = os.path.join(tmp, "result.json")
        vtu_path = os.path.join(tmp, "solution.vtu")
        with open(case_path, "w") as f:
            json.dump(case, f)
        cmd = [binary, "solve", case_path, "--out", out_path, "--quiet"]
        if vtu:
            cmd += ["--vtu", vtu_path, "--vtu-format", "ascii"]
        proc = subprocess.run(cmd, capture_output=True, text=True, env=env)
        if proc.returncode not in (0, 3, 4) or not os.path.exists(out_path):
            raise SolveError("%s exited with %d: %s" % (" ".join(cmd), proc.returncode,
                                                        proc.stderr.strip()))
        if proc.returncode == 3 and not allow_unconverged:
            raise SolveError("case %s did not converge" % case.get("name"))
        with open(out_path) as f:
            result = json.load(f)
        if vtu:
            result["vtu"] = read_vtu(vtu_path)
        return result


def read_vtu(path):
    """Points, triangles and the cell data arrays of the solver's ASCII VTU."""
    with open(path) as f:
        text = f.read()
    arrays = {}
    for header, body in re.findall(r"<DataArray([^>]*)>(.*?)</DataArray>", text, re.S):
        name = re.search(r'Name="([^"]*)"', header)
        arrays[name.group(1) if name else "points"] = [float(v) for v in body.split()]
    pts = arrays["points"]
    conn = [int(v) for v in arrays["connectivity"]]
    return {
        "points": [(pts[3 * i], pts[3 * i + 1]) for i in range(len(pts) // 3)],
        "triangles": [tuple(conn[3 * i:3 * i + 3]) for i in range(len(conn) // 3)],
        "functional": arrays.get("functional", []),
    }


def edge_length_range(points, triangles):
    """(h_min, h_max) over all edges of a triangle mesh, as Mesh::edge_length_range."""
    edges = set()
    for t in triangles:
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            edges.add((min(a, b), max(a, b)))
    lengths = [math.dist(points[a], points[b]) for a, b in edges]
    return min(lengths), max(lengths)


# --- cases ------------------------------------------------------------------------------------


def hertz_case(lam, refinements, displacement=None, radius=None, size=None, direction=None,
               method=None, max_iterations=None):
    """The shipped Hertz case (hertz or hertz_incompressible) with some fields replaced."""
    case = copy.deepcopy(load_example("hertz_incompressible" if lam == "inf" else "hertz"))
    case["material"]["lambda"] = lam
    case["mesh"]["refinements"] = refinements
    if size is not None:
        case["mesh"]["size"] = size
    if radius is not None:
        case["mesh"]["builtin"]["radius"] = radius
    if displacement is not None:
        case["boundary"]["top"]["displacement"] = [0, -displacement]
    if direction is not None:
        case["boundary"]["contact"]["direction"] = direction
    if method is not None:
        case["solver"]["method"] = method
    if max_iterations is not None:
        case["solver"]["max_iterations"] = max_iterations
    return case


def hertz_parameters(case):
    """(R, mu, lambda) of a Hertz case; lambda is float('inf') for "inf"."""
    builtin = case["mesh"]["builtin"]
    radius = float(builtin.get("radius", 1.0))
    mu = float(case["material"]["mu"])
    lam = case["material"]["lambda"]
    return radius, mu, math.inf if lam == "inf" else float(lam)


# --- Hertz reference --------------------------------------------------------------------------


def effective_modulus(mu, lam):
    """Plane-strain E* = 4μ(λ+μ)/(λ+2μ) against a rigid plane; 4μ for λ = ∞."""
    if math.isinf(lam):
        return 4.0 * mu
    return 4.0 * mu * (lam + mu) / (lam + 2.0 * mu)


def hertz_reference(force, radius, mu, lam):
    """Half-width a and peak pressure p0 of the plane-strain Hertz contact for the load F per
    unit thickness: a = √(4FR/(πE*)), p0 = 2F/(πa)."""
    e_star = effective_modulus(mu, lam)
    a = math.sqrt(4.0 * force * radius / (math.pi * e_star))
    return a, 2.0 * force / (math.pi * a)


def _hertz_integrals(x, a, p0):
    """Antiderivatives of p_H and p_H² in x at x (clipped to [−a, a])."""
    x = max(-a, min(a, x))
    root = math.sqrt(max(0.0, a * a - x * x))
    int_p = p0 / a * (0.5 * x * root + 0.5 * a * a * math.asin(x / a))
    int_p2 = p0 * p0 * (x - x ** 3 / (3.0 * a * a))
    return int_p, int_p2


def contact_edges(contact, radius):
    """Contact edges of the Hertz half disk (centre (0, R)) as (x_lo, x_hi, pressure), from the
    edge midpoints: a chord of the circle subtends 2·acos(|m − c|/R) about the direction of its
    midpoint, so its end points follow from the midpoint alone."""
    edges = []
    for x, y, p in zip(contact["x"], contact["y"], contact["pressure"]):
        dx, dy = x, y - radius
        dist = math.hypot(dx, dy)
        half = math.acos(min(1.0, dist / radius))
        phi = math.atan2(dx, -dy)  # angle from the downward vertical
        x1 = radius * math.sin(phi - half)
        x2 = radius * math.sin(phi + half)
        edges.append((min(x1, x2), max(x1, x2), p))
    edges.sort()
    return edges


def _mean_sqrt(lo, hi, a):
    """Mean of √(a − x)₊ over [lo, hi]."""
    def f(x):
        return max(0.0, a - x) ** 1.5
    return 2.0 / 3.0 * (f(lo) - f(hi)) / (hi - lo)


def half_width(edges):
    """Computed half-width a_h and the simpler extent of the loaded edges.

    Near the end x = a of a smooth frictionless contact the pressure behaves like c·√(a − x),
    and the pressure of an edge is the mean of σ_nn over it. On each side, a_h is the a for
    which the means of c·√(a − x)₊ over the two outermost loaded edges (p > 0) have the
    computed ratio (c cancels; the ratio is monotone in a, solved by bisection on the loaded
    edge and two edge lengths beyond it); with a single loaded edge on a side, its outer end.
    a_h is the mean of the two sides. The extent is the mean |x| of the outer ends of the
    outermost loaded edges."""
    loaded = [e for e in edges if e[2] > 0.0]
    if not loaded:
        return 0.0, 0.0
    interps, extents = [], []
    for sign in (1.0, -1.0):
        # Loaded edges of this side mirrored to x > 0, ordered from the centre outwards.
        side = sorted((min(sign * lo, sign * hi), max(sign * lo, sign * hi), p)
                      for lo, hi, p in loaded if sign * (lo + hi) > 0.0)
        if not side:
            interps.append(0.0)
            extents.append(0.0)
            continue
        extent = side[-1][1]
        interp = extent
        if len(side) >= 2:
            (lo1, hi1, p1), (lo2, hi2, p2) = side[-2], side[-1]

            def mismatch(a):
                return _mean_sqrt(lo2, hi2, a) / _mean_sqrt(lo1, hi1, a) - p2 / p1

            left, right = lo2 + 1e-12 * (hi2 - lo2), hi2 + 2.0 * (hi2 - lo2)
            if mismatch(left) * mismatch(right) <= 0.0:
                for _ in range(100):
                    mid = 0.5 * (left + right)
                    if mismatch(left) * mismatch(mid) <= 0.0:
                        right = mid
                    else:
                        left = mid
                interp = 0.5 * (left + right)
        interps.append(interp)
        extents.append(extent)
    return 0.5 * sum(interps), 0.5 * sum(extents)


def hertz_measures(result, case):
    """The numbers of the Hertz table for one solve."""
    radius, mu, lam = hertz_parameters(case)
    contact = result["contact"]
    force = abs(contact["force"][1])
    a, p0 = hertz_reference(force, radius, mu, lam)
    edges = contact_edges(contact, radius)
    a_h, a_extent = half_width(edges)
    p0_h = max(p for _, _, p in edges)
    err2 = ref2 = 0.0
    force_check = 0.0
    for lo, hi, p in edges:
        ip_lo, ip2_lo = _hertz_integrals(lo, a, p0)
        ip_hi, ip2_hi = _hertz_integrals(hi, a, p0)
        int_p, int_p2 = ip_hi - ip_lo, ip2_hi - ip2_lo
        err2 += p * p * (hi - lo) - 2.0 * p * int_p + int_p2
        ref2 += int_p2
        force_check += p * (hi - lo)
    central = min(edges, key=lambda e: abs(e[0] + e[1]))
    return {
        "dofs": result["dofs"],
        "iterations": result["iterations"],
        "converged": result["converged"],
        "h_contact": central[1] - central[0],
        "force": force,
        # Σ p Δx equals |F_y| for straight edges: a check of the edge reconstruction.
        "force_from_pressure": force_check,
        "a": a,
        "p0": p0,
        "a_h": a_h,
        "a_extent": a_extent,
        "p0_h": p0_h,
        "err_a": a_h / a - 1.0,
        "err_a_extent": a_extent / a - 1.0,
        "err_p0": p0_h / p0 - 1.0,
        "err_l2": math.sqrt(max(0.0, err2) / ref2),
        "functional": result["functional"]["total"],
        "functional_contact": result["functional"]["contact"],
        "a_over_R": a / radius,
    }


def profile_difference(coarse, fine):
    """Relative L2(dx) difference of two piecewise constant pressure profiles (lists of
    (x_lo, x_hi, p)), relative to the second: the discrete-reference error of a level."""
    cuts = sorted({x for lo, hi, _ in coarse + fine for x in (lo, hi)})

    def value(edges, x):
        for lo, hi, p in edges:
            if lo <= x <= hi:
                return p
        return 0.0

    diff2 = ref2 = 0.0
    for x0, x1 in zip(cuts, cuts[1:]):
        mid = 0.5 * (x0 + x1)
        pc, pf = value(coarse, mid), value(fine, mid)
        diff2 += (pc - pf) ** 2 * (x1 - x0)
        ref2 += pf * pf * (x1 - x0)
    return math.sqrt(diff2 / ref2)


def contact_zone(contact):
    """(x_min, x_max) of the contact edges with positive pressure."""
    xs = [x for x, p in zip(contact["x"], contact["pressure"]) if p > 0.0]
    return (min(xs), max(xs)) if xs else (0.0, 0.0)


def manufactured_case():
    """The manufactured-solution case file (tests/validation/manufactured_square.json)."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "manufactured_square.json")
    with open(path) as f:
        return json.load(f)
