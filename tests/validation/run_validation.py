#!/usr/bin/env python3
"""Regenerates docs/validation.md and docs/figures/*.png: the shipped benchmarks against the
plane-strain Hertz solution and against discrete references, the finite-body study, the
solvers' iteration counts and the FOSLS functional as an error estimator.

    python3 tests/validation/run_validation.py                 # everything, a few minutes
    python3 tests/validation/run_validation.py --reuse DATA     # only tables and figures

Needs a built fosls-contact and validation_manufactured_errors (default: build/bin), and
python3-numpy and python3-matplotlib for the figures. The raw numbers are kept in a JSON file
(--data, default build/validation-data.json) so that the document can be rewritten without
solving again (--reuse).
"""

import argparse
import copy
import json
import math
import os
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validation_lib as vl  # noqa: E402

from validation_document import write_document  # noqa: E402
from validation_study import (ESTIMATOR_LEVELS, ESTIMATOR_SCATTER, HERTZ_REFINEMENTS,  # noqa: E402
                              LOAD_CONFIGS, LOAD_REFINEMENTS, LOADS, METHOD_REFINEMENTS, PGS_CAP,
                              SIGNORINI_REFINEMENTS)


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# --- computations ----------------------------------------------------------------------------


def hertz_runs(binary, lam):
    rows = []
    for r in HERTZ_REFINEMENTS:
        case = vl.hertz_case(lam, r)
        t = time.time()
        result = vl.solve(binary, case)
        m = vl.hertz_measures(result, case)
        m["refinements"] = r
        m["wall_s"] = time.time() - t
        m["history"] = result["history"]
        m["contact"] = {k: result["contact"][k] for k in ("x", "y", "pressure")}
        m["edges"] = vl.contact_edges(result["contact"], 1.0)
        rows.append(m)
        log("hertz λ=%s r=%d: %d dofs, %d iterations, err a %+.4f, err p0 %+.4f, L2 %.4f"
            % (lam, r, m["dofs"], m["iterations"], m["err_a"], m["err_p0"], m["err_l2"]))
    finest = rows[-1]
    for m in rows:
        # The discrete reference: the finest level of the same sequence.
        m["ref_force"] = m["force"] / finest["force"] - 1.0
        m["ref_a"] = m["a_h"] / finest["a_h"] - 1.0
        m["ref_p0"] = m["p0_h"] / finest["p0_h"] - 1.0
        m["ref_l2"] = vl.profile_difference(m["edges"], finest["edges"])
    return rows


def coarse_mesh_ratio(binary, lam):
    case = vl.hertz_case(lam, 0)
    result = vl.solve(binary, case, vtu=True)
    h_min, h_max = vl.edge_length_range(result["vtu"]["points"], result["vtu"]["triangles"])
    return {"h_min": h_min, "h_max": h_max, "ratio": h_max / h_min,
            "triangles": len(result["vtu"]["triangles"])}


def finite_body_runs(binary):
    base = vl.load_example("hertz")
    d0 = -base["boundary"]["top"]["displacement"][1]
    size0 = base["mesh"]["size"]
    grading0 = base["mesh"]["builtin"]["grading"]
    rows = []
    for lam, direction in LOAD_CONFIGS:
        for d in LOADS:
            size = size0 * math.sqrt(d / d0)
            # Keep the far-field edge length of the shipped mesh: grading · size fixed.
            grading = min(100.0, max(1.0, grading0 * size0 / size))
            for r in LOAD_REFINEMENTS:
                case = vl.hertz_case(lam, r, displacement=d, size=size, direction=direction)
                case["mesh"]["builtin"]["grading"] = grading
                m = vl.hertz_measures(vl.solve(binary, case), case)
                rows.append({"lambda": lam, "direction": direction, "displacement": d,
                             "refinements": r, "size": size, "grading": grading,
                             **{k: m[k] for k in ("dofs", "force", "a", "a_over_R", "h_contact",
                                                  "err_a", "err_p0", "err_l2")}})
                log("finite body λ=%s %s d=%g r=%d: a/R %.3f err p0 %+.4f err a %+.4f"
                    % (lam, direction, d, r, m["a_over_R"], m["err_p0"], m["err_a"]))
    return rows


def method_runs(binary):
    """tnnmg, pdas and pgs on the Hertz cases (mmg: the runs of the Hertz table)."""
    rows = []
    for lam in (1, "inf"):
        for method, refinements in METHOD_REFINEMENTS.items():
            if method == "mmg":
                continue
            for r in refinements:
                case = vl.hertz_case(lam, r, method=method,
                                     max_iterations=PGS_CAP if method == "pgs" else None)
                t = time.time()
                result = vl.solve(binary, case, allow_unconverged=True)
                rows.append({"lambda": lam, "method": method, "refinements": r,
                             "dofs": result["dofs"], "iterations": result["iterations"],
                             "converged": result["converged"],
                             "force": abs(result["contact"]["force"][1]),
                             "wall_s": time.time() - t})
                log("method %s λ=%s r=%d: %d iterations%s" % (
                    method, lam, r, result["iterations"],
                    "" if result["converged"] else " (not converged)"))
    return rows


def all_method_rows(data):
    """The stored method runs plus mmg from the Hertz table."""
    rows = [m for m in data["methods"] if m["method"] != "mmg"]
    for lam in (1, "inf"):
        for m in data["hertz"][str(lam)]:
            if m["refinements"] in METHOD_REFINEMENTS["mmg"]:
                rows.append({"lambda": lam, "method": "mmg", "refinements": m["refinements"],
                             "dofs": m["dofs"], "iterations": m["iterations"],
                             "converged": m["converged"], "force": m["force"],
                             "wall_s": m["wall_s"]})
    return rows


def signorini_runs(binary):
    rows = []
    for name in ("signorini_square", "signorini_square_incompressible"):
        for r in SIGNORINI_REFINEMENTS:
            row = {"case": name, "refinements": r}
            for method in ("mmg", "pdas"):
                case = copy.deepcopy(vl.load_example(name))
                case["mesh"]["refinements"] = r
                case["solver"]["method"] = method
                result = vl.solve(binary, case)
                lo, hi = vl.contact_zone(result["contact"])
                row[method] = {"iterations": result["iterations"],
                               "force": result["contact"]["force"][1],
                               "zone": [lo, hi],
                               "p_max": max(result["contact"]["pressure"]),
                               "functional": result["functional"]["total"]}
                if method == "mmg":
                    row["dofs"] = result["dofs"]
                    row["contact"] = {k: result["contact"][k] for k in ("x", "pressure")}
            rows.append(row)
            log("signorini %s r=%d: F %.6f (pdas %.6f)" % (name, r, row["mmg"]["force"],
                                                           row["pdas"]["force"]))
    return rows


def estimator_runs(binary, estimator):
    out = {}
    for lam in ("1", "inf"):
        text = subprocess.run([estimator, "--lambda", lam, "--levels", str(ESTIMATOR_LEVELS),
                               "--elements", str(ESTIMATOR_SCATTER)],
                              check=True, capture_output=True, text=True).stdout
        out[lam] = json.loads(text)["rows"]
    # The same problem through the case JSON (expressions) and the CLI's iterative solver.
    case = vl.manufactured_case()
    result = vl.solve(binary, case)
    r = case["mesh"]["refinements"]
    out["cli_check"] = {"refinements": r, "cli_functional": result["functional"]["total"],
                        "tool_functional": out["1"][r]["functional"]["total"],
                        "iterations": result["iterations"]}
    log("estimator: CLI J %.10e, tool J %.10e" % (out["cli_check"]["cli_functional"],
                                                  out["cli_check"]["tool_functional"]))
    return out



def main():
    root = vl.ROOT
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bin", default=os.path.join(root, "build", "bin", "fosls-contact"))
    parser.add_argument("--estimator",
                        default=os.path.join(root, "build", "bin",
                                             "validation_manufactured_errors"))
    parser.add_argument("--docs", default=os.path.join(root, "docs"))
    parser.add_argument("--data", default=os.path.join(root, "build", "validation-data.json"))
    parser.add_argument("--reuse", action="store_true",
                        help="read the raw numbers from --data instead of solving")
    args = parser.parse_args()

    if args.reuse:
        with open(args.data) as f:
            data = json.load(f)
    else:
        for exe in (args.bin, args.estimator):
            if not os.access(exe, os.X_OK):
                sys.exit("not found: %s (build it, or pass --bin / --estimator)" % exe)
        t0 = time.time()
        data = {}
        data["mesh_ratio"] = coarse_mesh_ratio(args.bin, 1)
        data["hertz"] = {str(lam): hertz_runs(args.bin, lam) for lam in (1, "inf")}
        data["finite_body"] = finite_body_runs(args.bin)
        data["methods"] = method_runs(args.bin)
        data["signorini"] = signorini_runs(args.bin)
        data["estimator"] = estimator_runs(args.bin, args.estimator)
        data["wall_s"] = time.time() - t0
        os.makedirs(os.path.dirname(os.path.abspath(args.data)), exist_ok=True)
        with open(args.data, "w") as f:
            json.dump(data, f)
        log("raw numbers in %s (%.0f s)" % (args.data, data["wall_s"]))

    data["methods"] = all_method_rows(data)
    figures = os.path.join(args.docs, "figures")
    os.makedirs(figures, exist_ok=True)
    try:
        import plot_validation  # matplotlib only here: the tables need only the stdlib
    except ImportError as e:
        sys.exit("%s: the figures need python3-numpy and python3-matplotlib (Debian); if they "
                 "are installed, run this script with /usr/bin/python3. The raw numbers are "
                 "saved: rerun with --reuse --data %s" % (e, args.data))
    plot_validation.plot_all(data, figures, LOAD_REFINEMENTS, METHOD_REFINEMENTS)
    write_document(data, os.path.join(args.docs, "validation.md"))
    log("wrote %s and %s" % (os.path.join(args.docs, "validation.md"), figures))


if __name__ == "__main__":
    main()
