#pragma once
// A frictional solve of a discretisation (docs/method.md §8): the kinks of the slip and, for
// Coulomb friction, the slip bounds 𝔣 |S_n| updated from the iterate as it settles.

#include "assembly/discretization.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

/// Solves the finest level of `disc` with its friction (Coulomb: to options.friction_tolerance).
/// The bounds of the last update stay in the problem (the results' stick/slip states read
/// them).
SolverReport solve_frictional(Discretization<2>& disc, const LevelHierarchy& hierarchy,
                              const SolverOptions& options, const SolverObserver& observer,
                              Vector& x);

}  // namespace fosls
