"""The tables of docs/validation.md (sections 1–5) from run_validation.py's raw numbers, and the
fitted orders and rates their text quotes."""

import math

from validation_study import LOAD_CONFIGS, LOAD_REFINEMENTS, LOADS, METHOD_REFINEMENTS, lam_label


def pct(v, digits=2):
    return "%+.*f %%" % (digits, 100.0 * v)


def sci(v):
    return "%.2e" % v


def rate(values, hs):
    """Observed order between consecutive levels: log(e_i / e_{i+1}) / log(h_i / h_{i+1})."""
    out = [""]
    for i in range(1, len(values)):
        if values[i - 1] > 0 and values[i] > 0:
            out.append("%.2f" % (math.log(values[i - 1] / values[i]) / math.log(hs[i - 1] / hs[i])))
        else:
            out.append("")
    return out


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---:" for _ in header) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def hertz_table(rows):
    header = ["ref.", "DOFs", "h_c/a", "F", "a (Hertz)", "a_h", "err a", "err a (extent)",
              "p0 (Hertz)", "p0_h", "err p0", "L2 err p", "J^½", "mmg its"]
    body = [[m["refinements"], m["dofs"], "%.3f" % (m["h_contact"] / m["a"]),
             "%.5f" % m["force"], "%.5f" % m["a"], "%.5f" % m["a_h"], pct(m["err_a"]),
             pct(m["err_a_extent"]), "%.5f" % m["p0"], "%.5f" % m["p0_h"], pct(m["err_p0"]),
             "%.4f" % m["err_l2"], sci(math.sqrt(m["functional"])), m["iterations"]]
            for m in rows]
    return table(header, body)


def discrete_table(rows):
    header = ["ref.", "DOFs", "F − F_fine", "a_h − a_fine", "p0_h − p0_fine",
              "‖p_h − p_fine‖/‖p_fine‖", "order (profile)"]
    hs = [m["h_contact"] for m in rows[:-1]]
    orders = rate([m["ref_l2"] for m in rows[:-1]], hs)
    body = [[m["refinements"], m["dofs"], pct(m["ref_force"], 3), pct(m["ref_a"]),
             pct(m["ref_p0"]), "%.4f" % m["ref_l2"], o]
            for m, o in zip(rows[:-1], orders)]
    return table(header, body)


def finite_body_table(rows):
    header = ["λ", "direction", "top displacement", "a/R"]
    for r in LOAD_REFINEMENTS:
        header += ["err p0 (ref. %d)" % r, "err a (ref. %d)" % r, "L2 err p (ref. %d)" % r]
    body = []
    for lam, direction in LOAD_CONFIGS:
        for d in LOADS:
            sel = {m["refinements"]: m for m in rows
                   if m["lambda"] == lam and m["direction"] == direction
                   and m["displacement"] == d}
            row = [lam_label(lam), direction.replace("_", " "), "%g" % d,
                   "%.3f" % sel[LOAD_REFINEMENTS[-1]]["a_over_R"]]
            for r in LOAD_REFINEMENTS:
                row += [pct(sel[r]["err_p0"]), pct(sel[r]["err_a"]), "%.4f" % sel[r]["err_l2"]]
            body.append(row)
    return table(header, body)


def method_table(rows):
    header = ["λ", "ref.", "DOFs"] + list(METHOD_REFINEMENTS)
    body = []
    for lam in (1, "inf"):
        for r in range(0, max(max(v) for v in METHOD_REFINEMENTS.values()) + 1):
            sel = {m["method"]: m for m in rows if m["lambda"] == lam and m["refinements"] == r}
            cells = []
            for method in METHOD_REFINEMENTS:
                m = sel.get(method)
                if m is None:
                    cells.append("—")
                else:
                    cells.append(str(m["iterations"]) + ("" if m["converged"] else " (cap)"))
            dofs = next(iter(sel.values()))["dofs"]
            body.append([lam_label(lam), r, dofs] + cells)
    return table(header, body)


def signorini_table(rows, name):
    sel = [r for r in rows if r["case"] == name]
    fine = sel[-1]["mmg"]
    header = ["ref.", "DOFs", "F_y", "F_y − F_fine", "contact zone (edge midpoints)",
              "p_max", "J^½", "mmg its", "pdas its", "mmg vs pdas |ΔF|/F"]
    body = []
    for r in sel:
        m, p = r["mmg"], r["pdas"]
        body.append([r["refinements"], r["dofs"], "%.6f" % m["force"],
                     pct(m["force"] / fine["force"] - 1.0, 3) if r is not sel[-1] else "—",
                     "[%.4f, %.4f]" % tuple(m["zone"]), "%.4f" % m["p_max"],
                     sci(math.sqrt(m["functional"])), m["iterations"], p["iterations"],
                     "%.1e" % abs(m["force"] / p["force"] - 1.0)])
    return table(header, body)


def estimator_table(rows):
    header = ["ref.", "DOFs", "h", "J^½", "true error", "efficiency J^½/error",
              "local η_T/e_T: 5 %", "median", "95 %", "order J^½", "order error"]
    hs = [r["h_max"] for r in rows]
    oj = rate([math.sqrt(r["functional"]["total"]) for r in rows], hs)
    oe = rate([r["error"]["norm"] for r in rows], hs)
    body = []
    for r, a, b in zip(rows, oj, oe):
        le = r["local_efficiency"]
        body.append([r["refinements"], r["dofs"], "%.4f" % r["h_max"],
                     sci(math.sqrt(r["functional"]["total"])), sci(r["error"]["norm"]),
                     "%.3f" % r["efficiency"], "%.2f" % le["p05"], "%.2f" % le["median"],
                     "%.2f" % le["p95"], a, b])
    return table(header, body)


def mean_order(values, hs):
    """Least-squares slope of log(value) against log(h)."""
    xs = [math.log(h) for h in hs]
    ys = [math.log(v) for v in values]
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def linear_rate(history, tail=5):
    """Geometric mean KKT reduction over the last `tail` iterations."""
    kkt = [h["kkt_residual"] for h in history]
    tail = min(tail, len(kkt) - 1)
    return (kkt[-1] / kkt[-1 - tail]) ** (1.0 / tail) if tail > 0 else float("nan")


def hertz_estimator_table(rows):
    header = ["ref.", "J^½", "(J_contact)^½", "‖p_h − p_finest‖/‖p_finest‖",
              "ratio to J^½", "L2 err p vs Hertz", "ratio to J^½"]
    body = []
    for m in rows[:-1]:
        j = math.sqrt(m["functional"])
        body.append([m["refinements"], sci(j), sci(math.sqrt(max(0.0, m["functional_contact"]))),
                     "%.4f" % m["ref_l2"], "%.0f" % (m["ref_l2"] / j), "%.4f" % m["err_l2"],
                     "%.0f" % (m["err_l2"] / j)])
    return table(header, body)
