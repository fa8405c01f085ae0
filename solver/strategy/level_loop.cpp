#include "strategy/level_loop.hpp"

#include <algorithm>
#include <chrono>

#include "assembly/definiteness.hpp"
#include "assembly/error_indicators.hpp"
#include "assembly/solution_prolongation.hpp"
#include "core/indefinite_system.hpp"
#include "core/peak_memory.hpp"
#include "mesh/local_refinement.hpp"
#include "post/contact_force.hpp"
#include "solvers/solve_loop.hpp"
#include "strategy/friction_solve.hpp"
#include "strategy/order2_solve.hpp"

namespace fosls {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

template <int dim>
bool has_contact(const ProblemData<dim>& data) {
  return std::any_of(data.groups.begin(), data.groups.end(),
                     [](const GroupData<dim>& g) { return g.role == GroupRole::kContact; });
}

/// All DOFs of a mesh's space (order 1: d per vertex and per facet; order 2, 2D only: 2 per
/// vertex, 6 per edge, 4 per triangle): the measure of mesh.refinements', adaptivity.max_dofs'
/// and accuracy.max_dofs' limits.
template <class SimplexMeshType>
long long dofs_total(const SimplexMeshType& mesh, int order) {
  if constexpr (std::is_same_v<SimplexMeshType, Mesh>) {
    if (order == 2)
      return 2LL * mesh.num_vertices() + 6LL * mesh.num_edges() + 4LL * mesh.num_triangles();
  }
  return lowest_order_dofs(mesh);
}

/// The order-2 branch of solve_finest: the solve, and the solution's output from its
/// lowest-order interpolant.
void solve_finest_order2(LevelSolution<2>& solution, const SolverOptions& options,
                         const LevelLoopObserver& observer) {
  const auto t0 = Clock::now();
  const Discretization<2>& disc = *solution.disc;
  Order2Solution s = solve_order2(disc, *solution.order2, options, observer.solver);
  solution.assembly_s += s.assembly_s;
  solution.solve_s += seconds(t0, Clock::now()) - s.assembly_s;
  solution.assembly_mib = std::max(solution.assembly_mib, s.assembly_mib);
  solution.hierarchy_mib = s.hierarchy_mib;
  solution.report = std::move(s.report);
  solution.x = std::move(s.x);
  solution.full = std::move(s.interpolant);
  solution.parts = std::move(s.parts);
  solution.contact = contact_output(disc.assembler(), disc.problem(), solution.full);
  solution.force = {solution.contact.force_x, solution.contact.force_y};
}

/// The contact output of the solution in `solution.full`: 2D's ContactResult (whose force the
/// loop records), 3D's force (the rest of its output is contact_faces.hpp's).
template <int dim>
void evaluate_contact(LevelSolution<dim>& solution) {
  const Discretization<dim>& disc = *solution.disc;
  if constexpr (dim == 2) {
    solution.contact = contact_output(disc.assembler(), disc.problem(), solution.full);
    solution.force = {solution.contact.force_x, solution.contact.force_y};
  } else {
    const Vec<dim> f =
        contact_force(disc.finest_space(), solution.full, disc.problem().stress_scale);
    solution.force.assign(f.data(), f.data() + dim);
  }
}

/// The level's box QP solved: 2D's frictional contact by its own loop
/// (friction_solve.hpp), everything else by solve_box_qp.
template <int dim>
SolverReport solve_level(LevelSolution<dim>& solution, const LevelHierarchy& hierarchy,
                         const SolverOptions& options, const LevelLoopObserver& observer) {
  const AssembledProblem& problem = solution.disc->problem();
  if constexpr (dim == 2)
    if (!problem.friction.empty())
      return solve_frictional(*solution.disc, hierarchy, options, observer.solver, solution.x);
  return solve_box_qp(problem.qp, hierarchy, options, observer.solver, solution.x);
}

/// Solves the finest level of `solution.disc` from `solution.x` (empty: from the nested
/// iteration or zero) and evaluates the solution.
template <int dim>
void solve_finest(LevelSolution<dim>& solution, const LevelLoopOptions& loop, bool from_start,
                  bool first_step, const LevelLoopObserver& observer) {
  const auto t0 = Clock::now();
  const Discretization<dim>& disc = *solution.disc;
  const AssembledProblem& problem = disc.problem();
  // 3D's definiteness is checked by the solvers (chain_is_definite, CHOLMOD) only.
  if constexpr (dim == 2)
    if (has_contact(disc.data()) && !contact_layer_is_definite(disc.finest_space(), problem.qp))
      throw IndefiniteSystemError("the contact layer of the FOSLS matrix is not definite");
  SolverOptions options = loop.solver;
  // A prolongated (or continued) solution is a better start than the nested iteration would compute
  // again on all the coarser levels.
  if (from_start) options.nested = false;
  options.check_definiteness = first_step;
  if constexpr (dim == 2)
    if (solution.order2) {
      solve_finest_order2(solution, options, observer);
      return;
    }
  const bool adaptive_accuracy = loop.accuracy && loop.accuracy->adaptive;
  const double share =
      dim == 2 && adaptive_accuracy ? kAccuracySolverLevelShare : kMaxSolverLevelShare;
  const LevelHierarchy hierarchy =
      needs_level_hierarchy(options.method) ? disc.build_level_hierarchy(share) : LevelHierarchy{};
  // Without an iterate to return, a limit that passed while the hierarchy was built is still a
  // limit of the set-up (as in the assembly), not a solve stopped at its initial projection.
  if (!from_start) observer.deadline.check("building the level hierarchy");
  const auto t_assembled = Clock::now();
  solution.hierarchy_mib = peak_rss_mib();
  solution.report = solve_level(solution, hierarchy, options, observer);
  const auto t_solved = Clock::now();
  solution.assembly_s += seconds(t0, t_assembled);
  solution.solve_s += seconds(t_assembled, t_solved);
  solution.full = disc.assembler().full_vector(problem, solution.x);
  solution.parts = disc.assembler().functional(solution.full);
  solution.parts.friction = friction_functional(problem.friction, problem.kinks, solution.x);
  evaluate_contact(solution);
}

/// Why a loop of solves stops at this solve whatever it refines by, or empty. An unconverged
/// iterate would mark where the algebraic error is, and its force is not the level's.
std::string stop_for_the_solve(const SolverReport& report) {
  if (report.cancelled) return "cancelled";
  if (report.time_limited) return "time_limit";
  if (!report.converged) return "not_converged";
  return "";
}

/// Why the adaptive loop stops after this step's solve, or empty to go on.
template <int dim>
std::string stop_before_refining(const LevelSolution<dim>& s, const AdaptiveLoopOptions& a,
                                 int step, double first_estimator) {
  if (std::string reason = stop_for_the_solve(s.report); !reason.empty()) return reason;
  if (step >= a.steps) return "steps";
  if (a.target > 0 && s.steps.back().estimator <= a.target * first_estimator) return "target";
  return "";
}

template <int dim>
AdaptiveStepRecord step_record(const LevelSolution<dim>& solution, int step) {
  const Discretization<dim>& disc = *solution.disc;
  AdaptiveStepRecord record;
  record.step = step;
  record.levels = disc.num_levels();
  record.dofs = solution.dofs;
  record.dofs_total = solution.dofs_total;
  record.cells = disc.meshes().finest().num_cells();
  record.force = solution.force;
  record.iterations = solution.report.iterations;
  record.converged = solution.report.converged;
  record.converged_by = solution.report.converged_by;
  record.algebraic_error = solution.report.algebraic_error;
  return record;
}

/// The meshes of the next step, or why there is none.
template <int dim>
struct NextLevel {
  SimplexHierarchy<dim> meshes;
  SimplexBisectionState<dim> state;
  int marked = 0;
  std::string stop_reason;  ///< empty: refine
};

/// The adaptive loop's next level: the marked cells bisected (with closure). No cell marked
/// (J = 0) is the stop `if_none_marked`, or, without one, every cell bisected.
template <int dim>
NextLevel<dim> refine_marked(const LevelSolution<dim>& solution,
                             const SimplexBisectionState<dim>& state,
                             const std::vector<double>& indicators, double theta,
                             long long max_dofs, const char* if_none_marked) {
  std::vector<int> marked = dorfler_marking(indicators, theta);
  if (marked.empty() && !if_none_marked)
    for (int c = 0; c < static_cast<int>(indicators.size()); ++c) marked.push_back(c);
  NextLevel<dim> next{solution.disc->meshes(), state, static_cast<int>(marked.size()), ""};
  bisect_finest_level(next.meshes, next.state, marked);
  if (marked.empty())
    next.stop_reason = if_none_marked;
  else if (dofs_total(next.meshes.finest(), 1) > max_dofs)
    next.stop_reason = "max_dofs";
  return next;
}

/// The accuracy loop's next level: a uniform (red) refinement of the finest mesh.
template <int dim>
NextLevel<dim> refine_all(const LevelSolution<dim>& solution, const AccuracyLoopOptions& a,
                          int order) {
  NextLevel<dim> next{solution.disc->meshes(), {}, 0, ""};
  auto r = refine_all_cells(next.meshes.finest());
  if (dofs_total(r.fine, order) > a.max_dofs) {
    next.stop_reason = "max_dofs";
    return next;
  }
  next.marked = static_cast<int>(next.meshes.finest().num_cells());
  next.meshes.meshes.push_back(std::move(r.fine));
  next.meshes.maps.push_back(std::move(r.maps));
  return next;
}

std::vector<ForceComponents> forces(const std::vector<AdaptiveStepRecord>& steps) {
  std::vector<ForceComponents> f;
  for (const AdaptiveStepRecord& s : steps) f.push_back(s.force);
  return f;
}

/// The accuracy loop's estimate after the last of `steps`: from uniform levels by their ratio
/// of changes, from adaptive ones by their unknowns (force_accuracy.hpp).
template <int dim>
ForceErrorEstimate force_error_after(const std::vector<AdaptiveStepRecord>& steps,
                                     const AccuracyLoopOptions& a) {
  if (!a.adaptive) return estimate_force_error(forces(steps));
  std::vector<long long> dofs;
  for (const AdaptiveStepRecord& s : steps) dofs.push_back(s.dofs);
  return estimate_adaptive_force_error(forces(steps), dofs, dim);
}

/// The next level of the adaptive or the accuracy loop, or why there is none.
template <int dim>
NextLevel<dim> next_level(const LevelSolution<dim>& solution, const LevelLoopOptions& loop,
                          const SimplexBisectionState<dim>& state,
                          const std::vector<double>& indicators) {
  if (loop.adaptivity)
    return refine_marked(solution, state, indicators, loop.adaptivity->theta,
                         loop.adaptivity->max_dofs, "target");
  const AccuracyLoopOptions& a = *loop.accuracy;
  if (!a.adaptive) return refine_all(solution, a, loop.order);
  // J = 0 marks nothing: the force is then exact, and the next level (all cells bisected) says
  // so with a zero change.
  return refine_marked(solution, state, indicators, a.theta, a.max_dofs, nullptr);
}

/// Why the loop stops after this step's solve (before refining), or empty to go on.
template <int dim>
std::string stop_after_solve(const LevelSolution<dim>& solution, const LevelLoopOptions& loop,
                             int step, double first_estimator) {
  if (loop.adaptivity)
    return stop_before_refining(solution, *loop.adaptivity, step, first_estimator);
  if (std::string reason = stop_for_the_solve(solution.report); !reason.empty()) return reason;
  return accuracy_stop_reason(solution.steps.back().force_error, loop.accuracy->force,
                              forces(solution.steps));
}

}  // namespace

template <int dim>
LevelSolution<dim> solve_levels(SimplexHierarchy<dim> meshes, const ProblemData<dim>& data,
                                const LevelLoopOptions& loop, const LevelLoopObserver& observer,
                                const Vector* start) {
  constexpr int kPerLevel = kBisectionsPerUniformRefinement<dim>;
  LevelSolution<dim> solution;
  // The generation counts bisections from the coarse mesh (a red refinement is dim of them).
  // 3D marks its edges only when it will bisect: the marking of a large uniform mesh costs a
  // few per cent of its solve.
  SimplexBisectionState<dim> state;
  const bool bisects = loop.adaptivity || (loop.accuracy && loop.accuracy->adaptive);
  if (dim == 2 || bisects)
    state = initial_bisection_state(meshes.finest(), kPerLevel * (meshes.num_levels() - 1));
  double first_estimator = 0.0;
  int previous_levels = 0;  // of the step before: where its solution is prolongated from
  for (int step = 0;; ++step) {
    const auto t0 = Clock::now();
    solution.disc.reset();  // one level set in memory at a time
    // Only the first step has no iterate to stop at (a later one has the prolongated solution).
    solution.disc = std::make_unique<Discretization<dim>>(
        std::move(meshes), data, step == 0 ? observer.deadline : Deadline{});
    solution.assembly_s += seconds(t0, Clock::now());
    solution.assembly_mib = peak_rss_mib();
    const Discretization<dim>& disc = *solution.disc;
    solution.order2.reset();
    if constexpr (dim == 2)
      if (loop.order == 2)
        solution.order2 =
            std::make_unique<P2Rt1Space>(disc.meshes().finest(), data.boundary_roles());
    solution.dofs = solution.order2 ? solution.order2->num_free() : disc.problem().qp.size();
    solution.dofs_total =
        solution.order2 ? solution.order2->num_dofs() : disc.finest_space().num_dofs();
    // The order-2 solve starts from the nested iteration: the lowest-order iterate of a
    // continuation or of the level below is not one of its space.
    const bool started =
        step == 0 && start && !solution.order2 && start->size() == disc.problem().qp.size();
    if (started) solution.x = *start;
    if (step > 0 && !solution.order2)
      solution.x = prolongate_to_finest(disc, solution.full, previous_levels - 1);
    previous_levels = disc.num_levels();
    if (observer.on_step) observer.on_step(step, solution.dofs);
    solve_finest(solution, loop, (step > 0 && !solution.order2) || started, step == 0, observer);

    const ErrorEstimate estimate = error_estimate(solution.parts);
    solution.steps.push_back(step_record(solution, step));
    AdaptiveStepRecord& record = solution.steps.back();
    record.estimator = estimate.estimator();
    // An unconverged level's force is not the level's: no estimate from it (the loop stops).
    if (loop.accuracy && solution.report.converged)
      record.force_error = force_error_after<dim>(solution.steps, *loop.accuracy);
    if (step == 0) first_estimator = record.estimator;
    auto finish_step = [&] { solution.steps.back().time_s = seconds(t0, Clock::now()); };
    if (!loop.adaptivity && !loop.accuracy) {
      finish_step();
      break;
    }
    solution.stop_reason = stop_after_solve(solution, loop, step, first_estimator);
    NextLevel<dim> next;
    if (solution.stop_reason.empty()) {
      next = next_level(solution, loop, state, estimate.indicators);
      solution.stop_reason = next.stop_reason;
      if (solution.stop_reason.empty() && observer.deadline.passed())
        solution.stop_reason = "time_limit";
    }
    if (!solution.stop_reason.empty()) {
      finish_step();
      break;
    }
    record.marked = next.marked;
    meshes = std::move(next.meshes);
    if (bisects) state = std::move(next.state);
    finish_step();
  }
  // Levels added by a uniform accuracy loop: kPerLevel more bisections per level for every cell.
  if (loop.accuracy && !loop.accuracy->adaptive)
    state = initial_bisection_state(solution.disc->meshes().finest(),
                                    kPerLevel * (solution.disc->num_levels() - 1));
  solution.generation = std::move(state.generation);
  return solution;
}

template LevelSolution<2> solve_levels<2>(MeshHierarchy, const ProblemData<2>&,
                                          const LevelLoopOptions&, const LevelLoopObserver&,
                                          const Vector*);
template LevelSolution<3> solve_levels<3>(TetHierarchy, const ProblemData<3>&,
                                          const LevelLoopOptions&, const LevelLoopObserver&,
                                          const Vector*);

}  // namespace fosls
