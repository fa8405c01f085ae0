#pragma once
// The solve of a problem on its levels, in 2D and 3D: once on the uniformly refined hierarchy,
// or, with adaptivity options, the adaptive loop
//   solve → estimate (η_T² = the functional on T) → mark (Dörfler) → refine (newest-vertex
//   bisection of triangles or tetrahedra) → solve again from the prolongated solution
// in which every bisection step is one more level of the nested hierarchy that the multilevel
// solvers cycle on (coarse mesh, its uniform refinements, then the adapted meshes), or, with an
// accuracy options, the same loop on bisection steps or uniform refinements until the force's
// estimated error is within its tolerance. Written once for both dimensions; what stays 2D
// (order 2, friction inside the loop) is refused in 3D when a case is read
// (case/format/dimension_support.cpp). This layer knows no case: the case layer turns its
// sections into LevelLoopOptions and the records below into the result's JSON.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "assembly/discretization.hpp"
#include "core/deadline.hpp"
#include "fem/p2_rt1_space.hpp"
#include "mesh/simplex_mesh.hpp"
#include "post/contact_output.hpp"
#include "strategy/force_accuracy.hpp"
#include "strategy/level_loop_options.hpp"

namespace fosls {

/// One solve of the loop (docs/result-format.md: a step of `adaptivity.steps` or `accuracy.steps`).
struct AdaptiveStepRecord {
  int step = 0;
  int levels = 0;
  long long dofs = 0;        ///< unknowns solved for
  long long dofs_total = 0;  ///< all DOFs of the level
  long long cells = 0;       ///< triangles or tetrahedra of the finest mesh
  double estimator = 0.0;    ///< J^½ at the solution
  ForceComponents force;     ///< the contact force, dim components
  int iterations = 0;
  bool converged = false;
  ConvergedBy converged_by = ConvergedBy::kNone;
  /// The solve's estimated algebraic error (SolverReport::algebraic_error; infinite: unknown).
  double algebraic_error = 0.0;
  int marked = 0;                  ///< cells marked for the next refinement (0 on the last step)
  ForceErrorEstimate force_error;  ///< with an accuracy section (force_accuracy.hpp)
  double time_s = 0.0;
};

/// The solution on the finest level, and how it was reached.
template <int dim>
struct LevelSolution {
  std::unique_ptr<Discretization<dim>> disc;
  /// mesh.order 2 (2D only): the order-2 space on disc's finest mesh (docs/method.md §10);
  /// then x is its free DOFs, and full the lowest-order interpolant that the output is written
  /// from.
  std::unique_ptr<P2Rt1Space> order2;
  Vector x;     ///< free DOFs
  Vector full;  ///< all DOFs (rotated, scaled)
  FunctionalParts parts;
  /// 2D's contact output (a 3D result's is contact_faces.hpp's, from disc and full).
  ContactResult contact;
  ForceComponents force;               ///< the contact force, dim components
  SolverReport report;                 ///< of the last solve
  long long dofs = 0, dofs_total = 0;  ///< unknowns solved for and all DOFs of the last solve
  std::vector<AdaptiveStepRecord> steps;
  /// Why the adaptive loop stopped: "steps", "max_dofs", "target", "not_converged",
  /// "time_limit" or "cancelled"; the accuracy loop's: "reached", "no_force", "max_dofs",
  /// "not_converged", "time_limit" or "cancelled"; empty without either.
  std::string stop_reason;
  std::vector<int> generation;  ///< bisections from the coarse mesh, per finest cell
  double assembly_s = 0.0, solve_s = 0.0;
  /// Peak resident set after the last level's assembly and after its level hierarchy.
  double assembly_mib = 0.0, hierarchy_mib = 0.0;
};

/// Observers of the loop; every member is optional.
struct LevelLoopObserver {
  SolverObserver solver;
  /// Before each solve: the step (0 for the first) and the unknowns of its level.
  std::function<void(int step, long long dofs)> on_step;
  /// solver.time_limit_s: the first step's assembly polls it (TimeLimitReached: no iterate
  /// yet); a later step is not begun once it has passed (stop_reason "time_limit"), and its
  /// solve stops at the prolongated iterate if it passes while the step is assembled.
  Deadline deadline;
};

/// Solves on `meshes` and, when `options` ask for it, adapts or refines to an accuracy. `start`,
/// when given and of the finest level's size, is the first solve's initial iterate
/// (continuation; no nested iteration then). Throws IndefiniteSystemError when the weights make
/// the matrix indefinite.
template <int dim>
LevelSolution<dim> solve_levels(SimplexHierarchy<dim> meshes, const ProblemData<dim>& data,
                                const LevelLoopOptions& options,
                                const LevelLoopObserver& observer = {},
                                const Vector* start = nullptr);

}  // namespace fosls
