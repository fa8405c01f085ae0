#pragma once
// The solve loop shared by every method: it owns the stopping criteria (stopping_criterion.hpp),
// the norms, the history and the observer; the methods are iteration steps (iteration_step.hpp),
// the nested iteration a start (nested_iteration.hpp).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/box_qp.hpp"
#include "core/friction_law.hpp"
#include "core/kinks.hpp"
#include "core/level_hierarchy.hpp"
#include "solvers/coulomb_update.hpp"
#include "solvers/iteration_record.hpp"
#include "solvers/multilevel_cycle.hpp"
#include "solvers/stopping_criterion.hpp"

namespace fosls {

enum class SolverMethod {
  kMmg,    ///< monotone multilevel (Rovi, Kober, Starke, Krause 2019; docs/method.md §4)
  kTnnmg,  ///< truncated non-smooth Newton multigrid
  kPdas,   ///< primal–dual active set on a CHOLMOD factorisation (direct reference)
  kPgs,    ///< single-level projected Gauss–Seidel (pointwise or patch)
};

/// The method works on a level hierarchy: pdas solves the finest level directly and needs none
/// (pgs's patches are the finest level's of the hierarchy).
inline bool needs_level_hierarchy(SolverMethod method) { return method != SolverMethod::kPdas; }

/// When a solve has converged (docs/method.md §5.1).
enum class StoppingRule {
  kKktResidual,     ///< kkt_k ≤ tolerance · kkt_0
  kDiscretisation,  ///< that, or the algebraic error ≤ discretisation_fraction · J^½
};

struct SolverOptions {
  SolverMethod method = SolverMethod::kMmg;
  MultilevelOptions multilevel;  ///< smoother and smoothing steps are used by pgs and tnnmg too
  double tolerance = 1e-8;       ///< on kkt_k / kkt_0
  StoppingRule stopping = StoppingRule::kKktResidual;
  /// Of kDiscretisation: the algebraic error estimate (solvers/algebraic_error.hpp) allowed as a
  /// fraction of the discretisation error estimate J^½. pdas, not monotone, stops by the KKT
  /// test only.
  double discretisation_fraction = 0.1;
  int max_iterations = 200;
  /// Wall-clock seconds the whole run may take (0: no limit), from the start of the run
  /// (meshing and assembly included); the caller enforces it through SolverObserver::out_of_time.
  double time_limit_s = 0.0;
  /// Nested iteration (mmg and tnnmg): solve the Galerkin problems of the coarser levels
  /// (coarse obstacles by the same projections) coarsest first, each to `nested_tolerance`,
  /// and start the finest level from the prolongated solution, so that most of the search
  /// for the active set happens where it is cheap.
  bool nested = true;
  double nested_tolerance = 1e-3;
  int nested_max_iterations = 100;
  /// mmg and tnnmg: after each step, minimise J exactly over the plane of this step and the
  /// previous one, as far as the bounds allow (SubspaceAcceleration; docs/method.md §4.5).
  /// Still monotone and feasible; false runs the plain method.
  bool accelerate = true;
  /// mmg and tnnmg: run chain_is_definite before solving. An adaptive step after the first
  /// leaves it out: the weights were checked on the first step, and a step's check, a CHOLMOD
  /// factorisation of up to 5·10⁴ unknowns, is a large part of a small step (docs/performance.md,
  /// "Measurements behind choices in the code").
  bool check_definiteness = true;
  /// Coulomb friction: the largest relative change of the slip bounds at the last update for a
  /// solve to count as converged, unless that update moved the iterate by no more than the
  /// Coulomb residual that met the stopping criterion (docs/method.md §8.4).
  double friction_tolerance = 1e-6;
  /// Coulomb friction with mmg: where mmg stalls (solvers/coulomb_fallback.hpp), pdas finishes
  /// the solve from mmg's iterate, up to kFallbackMaxUnknowns unknowns (docs/method.md §8.4).
  bool coulomb_fallback = true;
  /// The KKT residual `tolerance` is relative to (0: the initial iterate's): a solve that
  /// continues another (Coulomb's fallback) keeps its predecessor's.
  double reference_kkt = 0.0;
};

struct SolverReport {
  bool converged = false;
  ConvergedBy converged_by = ConvergedBy::kNone;
  /// At the last iterate: E^½, E the estimated energy excess J(x) − J(x_h) (infinite when it
  /// could not be estimated; solvers/algebraic_error.hpp), and J^½.
  double algebraic_error = 0.0;
  double estimator = 0.0;
  bool cancelled = false;
  bool time_limited = false;  ///< stopped by SolverObserver::out_of_time
  int iterations = 0;
  double initial_kkt = 0.0;
  double final_kkt = 0.0;
  /// Geometric mean of the last (up to) 5 KKT reductions.
  double asymptotic_rate = 0.0;
  int active = 0;
  /// Iteration 0 (the initial iterate) and every iteration after it.
  std::vector<IterationRecord> history;
  double setup_s = 0.0;
  /// Of setup_s: the nested iteration on the coarser levels.
  double nested_s = 0.0;
  /// Iterations spent on each coarser level by the nested iteration (coarsest first).
  std::vector<int> nested_iterations;
  /// Iterations whose step the subspace acceleration changed (options.accelerate).
  int accelerated_steps = 0;
  double solve_s = 0.0;
  /// Peak resident set (MiB) after the Galerkin chain and after the whole set-up (0 where the
  /// method has no such stage).
  double chain_mib = 0.0;
  double setup_mib = 0.0;
  CycleStatistics cycle;
  std::string message;
  /// solve_kinked_qp with an update (Coulomb): the largest relative change of the slip bounds
  /// at each update, in order; the solve has converged only if the last is within tolerance.
  std::vector<double> update_changes;
  /// Coulomb with mmg: the loop stopped because mmg stalled (solvers/coulomb_fallback.hpp).
  bool stalled = false;
  /// The iteration after which pdas took over from a stalled mmg (0: it did not).
  int switched_at = 0;
};

/// The non-smooth parts of a frictional solve.
struct KinkedProblem {
  Kinks* kinks = nullptr;
  /// Coulomb friction: the frictional edges whose slip bounds follow the iterate
  /// (coulomb_update.hpp); null for fixed bounds (Tresca).
  const FrictionLayout* coulomb = nullptr;
  CoulombSchedule schedule;
};

/// The solve loop: minimises the bound-constrained QP from x (projected onto the bounds
/// first) by steps of the chosen method. The hierarchy is needed by mmg
/// and tnnmg only. Non-convergence is reported, not thrown; a matrix that is not positive
/// definite throws IndefiniteSystemError.
SolverReport solve_box_qp(const BoxQp& qp, const LevelHierarchy& hierarchy,
                          const SolverOptions& options, const SolverObserver& observer, Vector& x);

/// solve_box_qp for J + Σ w_k |x_k − o_k| (docs/method.md §8): methods mmg, pdas and pgs. The
/// QP's b and bounds change at the kinked DOFs during the solve (kink_sides.hpp) and are
/// restored; the bounds Coulomb's updates set stay. With Coulomb friction the bounds follow the
/// iterate (coulomb_update.hpp: at the start, as the schedule says and whenever a stopping
/// criterion is met), the stopping criteria measure the Coulomb residual, and the solve
/// converges when a criterion is met and the update then changes no bound by more than
/// options.friction_tolerance or moves x by no more than the residual that met it.
SolverReport solve_kinked_qp(BoxQp& qp, const KinkedProblem& kinked,
                             const LevelHierarchy& hierarchy, const SolverOptions& options,
                             const SolverObserver& observer, Vector& x);

/// solve_box_qp on the Galerkin chain of the hierarchy (formed here when null, for mmg and
/// tnnmg), without the definiteness check: the nested iteration's coarse solves.
SolverReport solve_with_chain(const BoxQp& qp, const LevelHierarchy& hierarchy,
                              const SolverOptions& options, const SolverObserver& observer,
                              Vector& x, std::shared_ptr<GalerkinChain> chain);

}  // namespace fosls
