#pragma once
// What the loop of solves over levels (level_loop.hpp) is asked to do: the solver, the order of
// the finest space, and either adaptive refinement for a number of steps or refinement until
// the force's estimated error is within a tolerance. The case layer fills it from a case's
// `solver`, `mesh.order`, `adaptivity` and `accuracy` sections (case/run/level_loop_options.cpp).

#include <optional>

#include "solvers/solve_loop.hpp"

namespace fosls {

/// Solve, estimate (η_T² = the functional on T), mark (Dörfler), bisect, solve again.
struct AdaptiveLoopOptions {
  int steps = 0;           ///< refinement steps at most (steps + 1 solves)
  long long max_dofs = 0;  ///< a refinement that would give more DOFs is not made
  double theta = 0.0;      ///< Dörfler parameter: refine the cells of θ of J
  double target = 0.0;     ///< stop once J^½ is `target` times its first value (0: none)
};

/// Refine until the force's estimated relative error (force_accuracy.hpp) is within `force`.
struct AccuracyLoopOptions {
  double force = 0.0;      ///< requested relative error of |F|
  long long max_dofs = 0;  ///< a refinement that would give more DOFs is not made
  bool adaptive = true;    ///< Dörfler marking and bisection; false: uniform (red) refinement
  double theta = 0.0;      ///< the Dörfler parameter of adaptive levels
};

struct LevelLoopOptions {
  SolverOptions solver;
  int order = 1;  ///< of the finest space: 2 is P2 × RT1 (2D only)
  std::optional<AdaptiveLoopOptions> adaptivity;
  std::optional<AccuracyLoopOptions> accuracy;  ///< not with adaptivity
};

}  // namespace fosls
