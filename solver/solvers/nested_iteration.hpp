#pragma once
// Nested iteration (mmg and tnnmg; SolverOptions::nested): the finest level's initial iterate
// from solves of the Galerkin problems of the coarser levels, coarsest first, each started from
// the prolongated solution of the one below, so that most of the search for the active set
// happens where it is cheap.

#include <functional>

#include "core/box_qp.hpp"
#include "core/level_hierarchy.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

/// The Galerkin problem of level j−1 seen from the problem of level j at x = 0: A_{j−1} = PᵀAP
/// (from the chain; c.A is left empty for the caller to lend it), b_{j−1} = Pᵀb and upper bounds
/// by the coarse-obstacle projection of the level-j bounds.
BoxQp coarser_problem(const BoxQp& fine, const Level& level, CoarseProjection projection);

/// Sets x to the prolongated, bound-clipped solution of the coarser levels' problems (each to
/// options.nested_tolerance; iterations per level appended to report.nested_iterations) and
/// returns true; returns false with x untouched when there is no coarser level or x = 0 is not
/// feasible (e.g. a negative gap), which the coarse problems assume. The chain's matrices are
/// lent to the coarse solves and returned, unchanged, however they end. `out_of_time`, when set,
/// stops each coarse solve at its last iterate once it returns true (solver.time_limit_s).
bool nested_initial_guess(const BoxQp& qp, const LevelHierarchy& h, const SolverOptions& options,
                          GalerkinChain& chain, Vector& x, SolverReport& report,
                          const std::function<bool()>& out_of_time = {});

}  // namespace fosls
