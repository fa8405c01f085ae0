#pragma once
// How much memory a case's solve needs, from its unknowns and its method, before it is solved:
// the service admits a case only when the estimate fits its per-job budget, and the CLI prints
// the estimate (`fosls-contact estimate`). The coefficients are measured, not derived:
// tests/benchmarks/memory_calibration.py re-measures them (docs/case-format.md, "Resources").

#include <cstddef>
#include <string>

#include "case/format/case_spec.hpp"
#include "mesh/mesh.hpp"

namespace fosls {

/// Peak resident memory of a solve ≈ base + bytes_per_unknown(method) · unknowns + a direct
/// factorisation: in 2D the base and slopes fitted over the Signorini square at 33 000 to
/// 2 100 000 unknowns (VTU included; tests/benchmarks/memory_calibration.py, docs/case-format.md
/// "Resources"), in 3D over the half ball and the box (docs/performance.md, "3D").
inline constexpr double kSolveBaseBytes = 17.9 * (1 << 20);
inline constexpr double kSolveBaseBytes3d = 40.0 * (1 << 20);

/// The fitted slope of a method, bytes per unknown of the finest level; for mesh.order 2 (a
/// matrix with about twice the entries per row, and the lowest-order level of the same mesh
/// below it) measured on the same square at 115 000 and 459 000 unknowns (docs/case-format.md,
/// "Resources").
double bytes_per_unknown(SolverMethod method, int order = 1, int dimension = 2);

/// The size of a case's discrete problem as admission counts it.
struct ProblemCount {
  long long unknowns = 0;  ///< of the finest level
  /// Of the coarsest level, which mmg and tnnmg factorise directly (CHOLMOD); 0: not known.
  long long coarse_unknowns = 0;
  bool exact = false;  ///< false when the coarse mesh was estimated, not built
  int order = 1;       ///< mesh.order
  int dimension = 2;
  /// Coulomb friction on some contact group: mmg may hand a stalled step to pdas, which
  /// factorises the whole problem (solvers/coulomb_fallback.hpp).
  bool coulomb = false;
};

/// 2D direct factorisations, bytes per N log₂ N (measured on the square at refinements 0, less
/// the base and the slope: docs/case-format.md, "Resources"): mmg's coarse solve holds two
/// factors (the held rows), pdas's one.
inline constexpr double kMultilevelCoarseBytes2d = 300;
inline constexpr double kPdasFactorBytes2d = 150;

/// The bytes of a direct factorisation of `unknowns` (held rows: two factors) by `method`'s
/// solver: nested dissection's fill grows like N log N in 2D and N^{4/3} in 3D; fitted on the
/// square and the box at refinements 0, where the coarse level is the whole problem
/// (docs/case-format.md, "Resources"). pgs factorises nothing.
double direct_factorisation_bytes(long long unknowns, SolverMethod method, int dimension);

/// Unknowns of the finest level (order 1: 2 per vertex and per edge; order 2: 2 per vertex, 6
/// per edge, 4 per triangle) after `refinements` red refinements of a coarse mesh with these
/// counts: each refinement adds a vertex per edge, halves every edge and adds three edges
/// inside every triangle, which it splits into four.
long long unknowns_after_refinement(long long triangles, long long edges, long long vertices,
                                    int refinements, int order = 1);

/// The same from a coarse triangle and boundary edge count only (estimated before meshing):
/// the other counts follow from Euler's formula for a disk. (A name of its own: as an overload
/// it won over the exact counts' version for a call with int counts.)
long long estimated_unknowns_after_refinement(double triangles, double boundary_edges,
                                              int refinements, int order = 1);

/// What admission and `fosls-contact estimate` report.
struct ResourceEstimate {
  long long unknowns = 0;
  bool unknowns_exact = false;  ///< false when the coarse mesh was estimated, not built
  double memory_bytes = 0;      ///< estimated peak resident memory of the solve
  /// The case field that sets the size: what to change when the estimate is too large.
  std::string limited_by = "/mesh/refinements";
  int order = 1;                  ///< mesh.order the estimate is for
  long long coarse_unknowns = 0;  ///< of the coarsest level (ProblemCount)
  int dimension = 2;
  /// Of memory_bytes, the direct factorisation of the coarsest level (mmg, tnnmg) or of the
  /// whole problem where it exceeds pdas's slope.
  double factorisation_bytes = 0;
  bool coulomb = false;  ///< ProblemCount::coulomb
  /// Of memory_bytes, what Coulomb's fallback to pdas adds to mmg's solve (0 where it cannot
  /// run): fallback_bytes().
  double fallback_bytes = 0;
  ProblemCount count() const {
    return {unknowns, coarse_unknowns, unknowns_exact, order, dimension, coulomb};
  }
};

/// What Coulomb's fallback adds to an mmg solve of `count` (0 where it cannot run: no Coulomb,
/// another method, 3D, or more unknowns than kFallbackMaxUnknowns): mmg's hierarchy and
/// iterate stay while pdas factorises the whole problem, so the peak is mmg's plus pdas's
/// above what the two share (the base and the finest level's matrix and vectors):
/// pdas's estimate less the base and mmg's slope. Measured with
/// tests/benchmarks/memory_calibration.py --coulomb (docs/case-format.md, "Resources").
double fallback_bytes(const ProblemCount& count, SolverMethod method);

/// mmg and tnnmg: their slope on the finest level and the direct factorisation of the coarsest,
/// mmg with Coulomb plus fallback_bytes(); pdas: the larger of its slope and the factorisation
/// of the whole problem; pgs: its slope.
ResourceEstimate estimate_resources(const ProblemCount& count, SolverMethod method);

/// An adaptive run's peak: its finest level has at most `max_dofs` unknowns, and mmg and tnnmg
/// keep every level of the bisection hierarchy, whose sizes fall by about 2/3 per level (about
/// 3 N in all against 4/3 N for uniform levels); 2.5 covers the measured factors with a margin
/// for deeper hierarchies (memory_calibration.py --adaptive, docs/case-format.md "Resources").
inline constexpr double kAdaptiveHierarchyFactor = 2.5;
/// `count` is the starting mesh's (its coarse level stays the hierarchy's coarsest).
ResourceEstimate estimate_adaptive_resources(long long max_dofs, const ProblemCount& count,
                                             SolverMethod method);

/// The unknowns of the finest level the accuracy loop may reach from `unknowns`: a level above
/// `max_dofs` is not made, and one up to it may be (a uniform refinement multiplies the DOFs by
/// 2.8–4, so no rule in between is safe for every mesh): max_dofs, as for adaptivity.
long long accuracy_largest_unknowns(long long unknowns, long long max_dofs);

/// A uniform refinement multiplies the DOFs by at least this (2.8 for a mesh of two triangles,
/// towards 4 for fine ones): an accuracy.max_dofs below unknowns times it leaves no second
/// level, and the estimate needs two.
constexpr double kAccuracyLeastGrowth = 2.5;

/// The estimate as one sentence ("about 1.2 GiB for 850 000 unknowns with mmg").
std::string describe(const ResourceEstimate& estimate, SolverMethod method);

}  // namespace fosls
