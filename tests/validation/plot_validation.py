"""Figures of docs/validation.md from the raw numbers of run_validation.py (matplotlib, Agg)."""

import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

LAMBDAS = [("1", "λ = 1"), ("inf", "λ = ∞")]
plt.rcParams.update({"font.size": 10, "axes.grid": True, "grid.alpha": 0.3,
                     "savefig.dpi": 130, "figure.dpi": 130})


def _save(fig, folder, name):
    fig.tight_layout()
    fig.savefig(os.path.join(folder, name))
    plt.close(fig)


def _steps(edges):
    """x and p arrays drawing a piecewise constant profile."""
    xs, ps = [], []
    for lo, hi, p in edges:
        xs += [lo, hi]
        ps += [p, p]
    return np.array(xs), np.array(ps)


def hertz_pressure(data, folder):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, (key, label) in zip(axes, LAMBDAS):
        rows = data["hertz"][key]
        fine, coarse = rows[-1], rows[2]
        a, p0 = fine["a"], fine["p0"]
        x = np.linspace(-1.6 * a, 1.6 * a, 801)
        ph = p0 * np.sqrt(np.clip(1.0 - x * x / (a * a), 0.0, None))
        xc, pc = _steps(coarse["edges"])
        ax.plot(xc, pc, color="tab:orange", lw=1.0,
                label="FOSLS, refinement %d (%d DOFs)" % (coarse["refinements"], coarse["dofs"]))
        xf, pf = _steps(fine["edges"])
        ax.plot(xf, pf, color="tab:blue", lw=1.2,
                label="FOSLS, refinement %d (%d DOFs)" % (fine["refinements"], fine["dofs"]))
        ax.plot(x, ph, "k--", lw=1.2,
                label="Hertz for the computed F = %.5f\n(a = %.4f, p0 = %.4f)" % (fine["force"], a, p0))
        ax.set_xlim(-1.6 * a, 1.6 * a)
        ax.set_ylim(0, 1.15 * max(p0, fine["p0_h"]))
        ax.set_xlabel("x (position along the plane, units of R)")
        ax.set_ylabel("contact pressure p = −σ_nn (units of μ)")
        ax.set_title("Hertz, %s: err a %+.2f %%, err p0 %+.2f %%, L² err %.3f"
                     % (label, 100 * fine["err_a"], 100 * fine["err_p0"], fine["err_l2"]))
        ax.legend(loc="lower center", fontsize=8)
    _save(fig, folder, "hertz_pressure.png")


def hertz_convergence(data, folder):
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex=True)
    for col, (key, label) in enumerate(LAMBDAS):
        rows = data["hertz"][key]
        h = np.array([m["h_contact"] / m["a"] for m in rows])
        ax = axes[0, col]
        ax.loglog(h, [m["err_l2"] for m in rows], "^-", color="tab:red",
                  label="‖p_h − p_Hertz‖ / ‖p_Hertz‖")
        ax.loglog(h[:-1], [m["ref_l2"] for m in rows[:-1]], "^--", color="tab:red", mfc="none",
                  label="‖p_h − p_finest‖ / ‖p_finest‖ (discrete reference)")
        ax.loglog(h[:-1], [max(abs(m["ref_a"]), 1e-5) for m in rows[:-1]], "o--",
                  color="tab:blue", mfc="none", label="|a_h / a_finest − 1|")
        ax.loglog(h[:-1], [max(abs(m["ref_p0"]), 1e-5) for m in rows[:-1]], "s--",
                  color="tab:green", mfc="none", label="|p0_h / p0_finest − 1|")
        ax.loglog(h, 0.8 * (h / h[0]) ** 0.5 * rows[0]["err_l2"], "k:", lw=0.8, label="order ½")
        ax.loglog(h, 0.8 * (h / h[0]) * rows[0]["err_l2"], "k-.", lw=0.8, label="order 1")
        ax.set_title("Hertz, %s: convergence" % label)
        ax.set_ylabel("relative error / difference")
        ax.legend(fontsize=7, loc="upper right")
        ax = axes[1, col]
        ax.semilogx(h, [100 * m["err_a"] for m in rows], "o-", color="tab:blue",
                    label="a_h (interpolated) vs Hertz")
        ax.semilogx(h, [100 * m["err_a_extent"] for m in rows], "o:", color="tab:blue",
                    mfc="none", label="a (extent of loaded edges) vs Hertz")
        ax.semilogx(h, [100 * m["err_p0"] for m in rows], "s-", color="tab:green",
                    label="p0_h vs Hertz")
        ax.axhspan(-3, 3, color="gray", alpha=0.12, label="±3 %")
        ax.axhline(0, color="k", lw=0.6)
        ax.set_ylim(-25, 25)
        ax.set_xlabel("h_c / a (central contact edge / Hertz half-width; finer to the right)")
        ax.set_ylabel("signed relative error (%)")
        ax.set_title("Hertz, %s: a and p0 against Hertz" % label)
        ax.legend(fontsize=7, loc="lower right")
    axes[0, 0].invert_xaxis()  # all four share x: coarse left, fine right
    for ax in axes.flat:
        ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%.3g"))
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xticks([0.02, 0.05, 0.1, 0.2, 0.5])
    _save(fig, folder, "hertz_convergence.png")


def hertz_finite_body(data, folder, refinements):
    rows = data["finite_body"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    configs = [(1, "body_normal", "tab:blue", "λ = 1, body normal"),
               (1, "obstacle_normal", "tab:green", "λ = 1, obstacle normal"),
               ("inf", "body_normal", "tab:red", "λ = ∞")]
    markers = {refinements[0]: ("o", "--"), refinements[-1]: ("s", "-")}
    for ax, field, title in [(axes[0], "err_p0", "peak pressure p0"),
                             (axes[1], "err_a", "half-width a (interpolated)")]:
        for lam, direction, color, label in configs:
            for r in refinements:
                sel = sorted((m for m in rows if m["lambda"] == lam
                              and m["direction"] == direction and m["refinements"] == r),
                             key=lambda m: m["a_over_R"])
                marker, ls = markers[r]
                ax.plot([m["a_over_R"] for m in sel], [100 * m[field] for m in sel],
                        marker=marker, ls=ls, color=color,
                        label="%s, refinement %d" % (label, r))
        ax.axhline(0, color="k", lw=0.6)
        ax.axhspan(-3, 3, color="gray", alpha=0.08)
        ax.set_xlabel("a / R (load varied, h/a fixed)")
        ax.set_ylabel("relative error against Hertz (%)")
        ax.set_title(title)
    axes[0].legend(fontsize=7, loc="upper left")
    _save(fig, folder, "hertz_finite_body.png")


def kkt_history(data, folder):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    cmap = plt.get_cmap("viridis")
    for ax, (key, label) in zip(axes, LAMBDAS):
        rows = [m for m in data["hertz"][key] if m["refinements"] >= 1]
        for i, m in enumerate(rows):
            color = cmap(0.85 * i / max(1, len(rows) - 1))  # no pale yellow
            it = [h["iteration"] for h in m["history"]]
            kkt = [h["kkt_residual"] for h in m["history"]]
            ax.semilogy(it, kkt, "-", color=color,
                        label="refinement %d (%d levels, %d DOFs)"
                        % (m["refinements"], m["refinements"] + 1, m["dofs"]))
            changed = [(h["iteration"], h["kkt_residual"]) for h in m["history"] if h["changed"] > 0]
            if changed:
                ax.semilogy(*zip(*changed), "o", color=color, mfc="none", ms=7)
        ax.plot([], [], "o", color="gray", mfc="none", label="active set changed")
        ax.set_xlabel("iteration (finest level)")
        if key == "1":
            ax.set_ylabel("KKT residual ‖x − P_K(x − ∇J)‖")
        ax.set_title("mmg on Hertz, " + label)
        ax.legend(fontsize=7.5)
    _save(fig, folder, "hertz_kkt_history.png")


def solver_iterations(data, folder, method_refinements):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    styles = {"mmg": "o-", "tnnmg": "s-", "pdas": "^-", "pgs": "D-"}
    for ax, (key, label) in zip(axes, LAMBDAS):
        for method in method_refinements:
            sel = sorted((m for m in data["methods"]
                          if str(m["lambda"]) == key and m["method"] == method),
                         key=lambda m: m["refinements"])
            levels = [m["refinements"] + 1 for m in sel]
            its = [m["iterations"] for m in sel]
            line, = ax.semilogy(levels, its, styles[method], label=method)
            capped = [(lv, m["iterations"]) for lv, m in zip(levels, sel) if not m["converged"]]
            if capped:
                ax.semilogy(*zip(*capped), "x", color=line.get_color(), ms=10,
                            label=method + ": cap reached")
        ax.set_xlabel("levels (refinements + 1)")
        ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
        if key == "1":
            ax.set_ylabel("iterations to 10⁻⁸ relative KKT residual")
        ax.set_title("Hertz, " + label)
        ax.legend(fontsize=8)
    _save(fig, folder, "solver_iterations.png")


def signorini_pressure(data, folder):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.0), sharey=True)
    for ax, name, label in [(axes[0], "signorini_square", "λ = 1"),
                            (axes[1], "signorini_square_incompressible", "λ = ∞")]:
        rows = [r for r in data["signorini"] if r["case"] == name]
        for r in rows[1::2] + ([rows[-1]] if len(rows) % 2 == 1 else []):
            xs, ps = r["contact"]["x"], r["contact"]["pressure"]
            ax.plot(xs, ps, ".-", ms=3, lw=0.9,
                    label="refinement %d (%d DOFs)" % (r["refinements"], r["dofs"]))
        ax.set_xlabel("x (bottom edge)")
        if name == "signorini_square":
            ax.set_ylabel("contact pressure (units of μ)")
        ax.set_title("Signorini square, %s: pressure at the edge midpoints" % label)
        ax.legend(fontsize=8, loc="upper right")
    _save(fig, folder, "signorini_pressure.png")


def estimator(data, folder):
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    ax = axes[0]
    for (key, label), color in zip(LAMBDAS, ("tab:blue", "tab:red")):
        rows = data["estimator"][key]
        dofs = [r["dofs"] for r in rows]
        ax.loglog(dofs, [math.sqrt(r["functional"]["total"]) for r in rows], "o-", color=color,
                  label="J^½, " + label)
        ax.loglog(dofs, [r["error"]["norm"] for r in rows], "s--", color=color, mfc="none",
                  label="true error ‖(u − u_h, σ − σ_h)‖, " + label)
    d = np.array([r["dofs"] for r in data["estimator"]["1"]], dtype=float)
    ax.loglog(d, 2.0 * (d / d[0]) ** -0.5 * math.sqrt(data["estimator"]["1"][0]["functional"]["total"]),
              "k:", lw=0.8, label="slope −½ (order 1 in h)")
    ax.set_xlabel("DOFs")
    ax.set_ylabel("H¹ × H(div) norm")
    ax.set_title("Manufactured solution: estimator and error")
    ax.legend(fontsize=7.5)
    ax = axes[1]
    for (key, label), color in zip(LAMBDAS, ("tab:blue", "tab:red")):
        rows = data["estimator"][key]
        lv = np.array([r["refinements"] for r in rows]) + (0.05 if key == "inf" else -0.05)
        le = [r["local_efficiency"] for r in rows]
        ax.plot(lv, [r["efficiency"] for r in rows], "o-", color=color,
                label="efficiency index J^½ / error, " + label)
        ax.errorbar(lv, [q["median"] for q in le],
                    yerr=[[q["median"] - q["p05"] for q in le], [q["p95"] - q["median"] for q in le]],
                    fmt="_", color=color, alpha=0.6, capsize=3,
                    label="local η_T/e_T: median, 5–95 %%, %s" % label)
    ax.set_ylim(0, 1.1)
    ax.set_xlabel("refinements")
    ax.set_ylabel("efficiency")
    ax.set_title("Efficiency over the levels")
    ax.legend(fontsize=7.5, loc="lower right")
    ax = axes[2]
    for (key, label), color in zip(LAMBDAS, ("tab:blue", "tab:red")):
        row = next(r for r in data["estimator"][key] if "element_error" in r)
        e = np.sqrt(np.array(row["element_error"]))
        eta = np.sqrt(np.clip(np.array(row["element_functional"]), 0.0, None))
        ax.loglog(e, eta, ".", ms=2, alpha=0.35, color=color,
                  label="%s (%d triangles, refinement %d)" % (label, len(e), row["refinements"]))
    lims = np.array([e.min() * 0.7, e.max() * 1.4])
    ax.loglog(lims, lims, "k-", lw=0.8, label="η_T = e_T")
    ax.loglog(lims, 0.5 * lims, "k--", lw=0.8, label="η_T = e_T / 2")
    ax.set_xlabel("true element error e_T")
    ax.set_ylabel("element estimator η_T = J_T^½")
    ax.set_title("Element by element")
    ax.legend(fontsize=7.5, loc="upper left", markerscale=4)
    _save(fig, folder, "estimator_efficiency.png")


def plot_all(data, folder, load_refinements, method_refinements):
    hertz_pressure(data, folder)
    hertz_convergence(data, folder)
    hertz_finite_body(data, folder, load_refinements)
    kkt_history(data, folder)
    solver_iterations(data, folder, method_refinements)
    signorini_pressure(data, folder)
    estimator(data, folder)
