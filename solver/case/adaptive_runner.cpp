#include "case/adaptive_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "assembly/definiteness.hpp"
#include "assembly/error_indicators.hpp"
#include "assembly/solution_prolongation.hpp"
#include "case/friction_solve.hpp"
#include "case/solver_methods.hpp"
#include "core/indefinite_system.hpp"
#include "core/peak_memory.hpp"
#include "mesh/bisection.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

bool has_contact(const ProblemData& data) {
  return std::any_of(data.groups.begin(), data.groups.end(),
                     [](const GroupData& g) { return g.role == GroupRole::kContact; });
}

/// All DOFs of a mesh's space (2 per vertex, 2 per edge): the measure of mesh.refinements'
/// and adaptivity.max_dofs' limits.
long long dofs_total(const Mesh& mesh) { return 2LL * (mesh.num_vertices() + mesh.num_edges()); }

/// Solves the finest level of `solution.disc` from `solution.x` (empty: from the nested
/// iteration or zero) and evaluates the solution.
void solve_finest(CaseSolution& solution, const CaseSpec& spec, bool from_start, bool first_step,
                  const CaseSolveObserver& observer) {
  const auto t0 = Clock::now();
  const Discretization& disc = *solution.disc;
  const AssembledProblem& problem = disc.problem();
  if (has_contact(disc.data()) && !contact_layer_is_definite(disc.finest_space(), problem.qp))
    throw IndefiniteSystemError("the contact layer of the FOSLS matrix is not definite");
  SolverOptions options = spec.solver;
  // A prolongated (or continued) solution is a better start than the nested iteration would compute
  // again on all the coarser levels.
  if (from_start) options.nested = false;
  options.check_definiteness = first_step;
  const LevelHierarchy hierarchy =
      method_info(options.method).needs_hierarchy ? disc.build_level_hierarchy() : LevelHierarchy{};
  const auto t_assembled = Clock::now();
  solution.hierarchy_mib = peak_rss_mib();
  solution.report =
      problem.friction.empty()
          ? solve_box_qp(problem.qp, hierarchy, options, observer.solver, solution.x)
          : solve_frictional(*solution.disc, hierarchy, options, observer.solver, solution.x);
  const auto t_solved = Clock::now();
  solution.assembly_s += seconds(t0, t_assembled);
  solution.solve_s += seconds(t_assembled, t_solved);
  solution.full = disc.assembler().full_vector(problem, solution.x);
  solution.parts = disc.assembler().functional(solution.full);
  solution.parts.friction = friction_functional(problem.friction, problem.kinks, solution.x);
  solution.contact = contact_output(disc.assembler(), problem, solution.full);
}

/// Why the loop stops after this step's solve, or empty to go on.
std::string stop_before_refining(const CaseSolution& s, const AdaptivitySpec& a, int step,
                                 double first_estimator) {
  if (s.report.cancelled) return "cancelled";
  if (s.report.time_limited) return "time_limit";
  // Marking from an unconverged iterate would refine where the algebraic error is.
  if (!s.report.converged) return "not_converged";
  if (step >= a.steps) return "steps";
  if (a.target > 0 && s.steps.back().estimator <= a.target * first_estimator) return "target";
  return "";
}

}  // namespace

CaseSolution solve_case_levels(MeshHierarchy meshes, const ProblemData& data, const CaseSpec& spec,
                               const CaseSolveObserver& observer, const Vector* start) {
  CaseSolution solution;
  // A red refinement is two bisections: the generation counts bisections from the coarse mesh.
  BisectionState state = longest_edge_state(meshes.finest(), 2 * (meshes.num_levels() - 1));
  double first_estimator = 0.0;
  for (int step = 0;; ++step) {
    const auto t0 = Clock::now();
    solution.disc.reset();  // one level set in memory at a time
    // Only the first step has no iterate to stop at (a later one has the prolongated solution).
    solution.disc = std::make_unique<Discretization>(std::move(meshes), data,
                                                     step == 0 ? observer.deadline : Deadline{});
    solution.assembly_s += seconds(t0, Clock::now());
    solution.assembly_mib = peak_rss_mib();
    const Discretization& disc = *solution.disc;
    const bool started = step == 0 && start && start->size() == disc.problem().qp.size();
    if (started) solution.x = *start;
    if (step > 0) solution.x = prolongate_to_finest(disc, solution.full);
    if (observer.on_step) observer.on_step(step, disc.problem().qp.size());
    solve_finest(solution, spec, step > 0 || started, step == 0, observer);

    const ErrorEstimate estimate = error_estimate(solution.parts);
    const Mesh& finest = disc.meshes().finest();
    AdaptiveStepRecord record;
    record.step = step;
    record.levels = disc.num_levels();
    record.dofs = disc.problem().qp.size();
    record.dofs_total = disc.finest_space().num_dofs();
    record.triangles = finest.num_triangles();
    record.estimator = estimate.estimator();
    record.force = {solution.contact.force_x, solution.contact.force_y};
    record.iterations = solution.report.iterations;
    record.converged = solution.report.converged;
    record.converged_by = solution.report.converged_by;
    record.algebraic_error = solution.report.algebraic_error;
    if (step == 0) first_estimator = record.estimator;
    solution.steps.push_back(record);
    auto finish_step = [&] { solution.steps.back().time_s = seconds(t0, Clock::now()); };
    if (!spec.adaptivity) {
      finish_step();
      break;
    }
    const AdaptivitySpec& a = *spec.adaptivity;
    solution.stop_reason = stop_before_refining(solution, a, step, first_estimator);
    if (!solution.stop_reason.empty()) {
      finish_step();
      break;
    }
    const std::vector<int> marked = dorfler_marking(estimate.indicators, a.theta);
    MeshHierarchy next = disc.meshes();
    BisectionState next_state = state;
    refine_finest_level(next, next_state, marked);
    if (marked.empty() || dofs_total(next.finest()) > a.max_dofs || observer.deadline.passed()) {
      solution.stop_reason = marked.empty()                           ? "target"
                             : dofs_total(next.finest()) > a.max_dofs ? "max_dofs"
                                                                      : "time_limit";
      finish_step();
      break;
    }
    solution.steps.back().marked = static_cast<int>(marked.size());
    meshes = std::move(next);
    state = std::move(next_state);
    finish_step();
  }
  solution.generation = std::move(state.generation);
  return solution;
}

nlohmann::json adaptivity_json(const CaseSolution& solution, const AdaptivitySpec& spec) {
  nlohmann::json steps = nlohmann::json::array();
  for (const AdaptiveStepRecord& s : solution.steps)
    steps.push_back(
        {{"step", s.step},
         {"levels", s.levels},
         {"dofs", s.dofs},
         {"dofs_total", s.dofs_total},
         {"triangles", s.triangles},
         {"estimator", s.estimator},
         {"force", s.force},
         {"iterations", s.iterations},
         {"converged", s.converged},
         {"converged_by", converged_by_name(s.converged_by)},
         {"algebraic_error",
          std::isfinite(s.algebraic_error) ? nlohmann::json(s.algebraic_error) : nlohmann::json()},
         {"marked", s.marked},
         {"time_s", s.time_s}});
  nlohmann::json a = {{"theta", spec.theta},
                      {"max_dofs", spec.max_dofs},
                      {"target", spec.target},
                      {"stop_reason", solution.stop_reason},
                      {"steps", steps}};
  add_adaptive_summary(a, solution, spec);
  return a;
}

}  // namespace fosls
