"""The validation study's parameters (docs/validation.md, sections 1–5): which levels, loads and
methods run_validation.py solves and validation_document.py reports."""

# The Hertz table: refinements 0..5 of the shipped cases (levels 1..6).
HERTZ_REFINEMENTS = list(range(0, 6))
# Finite-body study: top displacements (the load), at two refinements; the coarse mesh size
# near the contact is scaled with a ∝ √d so that every load is resolved alike (h/a fixed).
LOADS = [0.0025, 0.005, 0.01, 0.02, 0.04]
LOAD_REFINEMENTS = [3, 4]
LOAD_CONFIGS = [(1, "body_normal"), (1, "obstacle_normal"), ("inf", "body_normal")]
# Solver comparison on the Hertz cases; PGS is far too slow beyond the first levels.
METHOD_REFINEMENTS = {"mmg": range(0, 6), "tnnmg": range(0, 5), "pdas": range(0, 5),
                      "pgs": range(0, 2)}
PGS_CAP = 60000
SIGNORINI_REFINEMENTS = list(range(0, 6))
ESTIMATOR_LEVELS = 6
ESTIMATOR_SCATTER = 3  # refinement whose element-wise values are plotted


def lam_label(lam):
    return "∞" if lam == "inf" else str(lam)
