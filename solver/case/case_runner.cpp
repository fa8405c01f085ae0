#include "case/case_runner.hpp"

#include "case/load_step_runner.hpp"
#include "case/solve3d_backend.hpp"
#include "case/solve_observer.hpp"
#include "case/sweep_runner.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "assembly/contact_weight.hpp"
#include "case/adaptive_runner.hpp"
#include "case/case_admission.hpp"
#include "case/case_problem_data.hpp"
#include "case/expression.hpp"
#include "case/mesh_factory.hpp"
#include "case/result_annotations.hpp"
#include "case/result_json.hpp"
#include "case/solver_methods.hpp"
#include "core/indefinite_system.hpp"
#include "core/non_finite.hpp"
#include "core/peak_memory.hpp"
#include "mesh/length_scale.hpp"
#include "post/vtu_writer.hpp"

namespace fosls {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// Problems that need the coarse mesh: unknown groups, no Dirichlet group, size limits.
std::vector<CaseError> check_against_mesh(const CaseSpec& spec, const Mesh& mesh,
                                          const CaseLimits& limits) {
  const auto unknowns = [&mesh](int refinements, int order) {
    return unknowns_after_refinement(mesh.num_triangles(), mesh.num_edges(), mesh.num_vertices(),
                                     refinements, order);
  };
  return check_against_groups(
      spec, mesh.group_names(),
      {unknowns(spec.mesh.refinements, spec.mesh.order), unknowns(0, 1), true, spec.mesh.order, 2},
      limits);
}

/// What a run stopped by its time limit before the first iterate says (no result to return).
std::string time_limit_message(const CaseSpec& spec, const std::string& stage) {
  std::ostringstream m;
  m << "solver.time_limit_s (" << spec.solver.time_limit_s << " s) ran out while " << stage
    << ", before the solve had a first iterate, so there is no result to return; raise "
       "solver.time_limit_s, or use fewer mesh.refinements or a coarser mesh.size";
  if (!spec.sweep_points.empty()) m << " (each sweep point has the whole limit)";
  return m.str();
}

bool has_roller(const CaseSpec& spec) {
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kDirichlet && !(bc.prescribed[0] && bc.prescribed[1]))
      return true;
  return false;
}

/// `spec` carries the weights as used (c3 chosen when "auto").
CaseException indefinite(const CaseSpec& spec, const MeshHierarchy& meshes,
                         const ProblemData<2>& data) {
  const Weights& w = spec.weights;
  std::ostringstream m;
  m << "the weights c1 = " << w.c1 << ", c2 = " << w.c2 << ", c3 = " << w.c3 << ", c4 = " << w.c4
    << ", c2_volumetric = " << w.c2_volumetric
    << " make the FOSLS matrix indefinite (the contact term c3 is too large relative to c1 and "
       "c2)";
  if (w.c3_auto) {
    m << "; c3 was chosen as half the limit " << w.c3_limit
      << " computed on a coarser level, and the finest level's limit is lower: set c3 below "
         "that by hand";
  } else {
    const ContactWeightLimit limit = contact_weight_limit(meshes, data);
    m << "; on this mesh c3 must stay below about " << limit.limit << " (computed on level "
      << limit.level << ", " << limit.dofs
      << " unknowns): remove c3 from the case (or give \"auto\") to have it chosen";
  }
  // A body held only by rollers may keep a rigid rotation: that looks the same to the check.
  if (has_roller(spec))
    m << ". With null displacement components, also check that the dirichlet groups leave no "
         "rigid motion (a rotation needs two points held across it)";
  return CaseException("/weights", m.str());
}

}  // namespace

Deadline run_deadline(Clock::time_point start, double time_limit_s) {
  if (time_limit_s <= 0) return {};
  return Deadline(start + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(time_limit_s)));
}

std::vector<CaseError> validate_case(const nlohmann::json& j, const CaseReadOptions& options,
                                     const MeshingControl& meshing) {
  CaseReadResult read = read_case(j, options);
  if (!read.errors.empty()) return read.errors;
  if (read.spec->dimension == 3) {
    // The groups' rule here, the size and what the mesh shows once it is built.
    std::vector<CaseError> errors =
        check_against_groups(*read.spec, std::nullopt, ProblemCount{}, CaseLimits{});
    return errors.empty() ? check_3d_mesh(*read.spec, options.limits) : errors;
  }
  try {
    const Mesh mesh = build_coarse_mesh(read.spec->mesh, meshing);
    return check_against_mesh(*read.spec, mesh, options.limits);
  } catch (const CaseException& e) {
    return e.errors();
  }
}

namespace {

/// u at every vertex from a full (rotated) DOF vector.
std::vector<Point> vertex_displacements(const FoslsSpace<2>& space, const Vector& x_full) {
  const Vector cartesian = space.rotation() * x_full;
  std::vector<Point> u(space.mesh().num_vertices());
  for (int v = 0; v < static_cast<int>(u.size()); ++v)
    u[v] = Point(cartesian[space.u_dof(v, 0)], cartesian[space.u_dof(v, 1)]);
  return u;
}

RunOutput run_point(const CaseSpec& spec, const RunControl& control, const CaseLimits& limits) {
  const auto t0 = Clock::now();
  Mesh coarse;
  try {
    coarse = build_coarse_mesh(spec.mesh, MeshingControl{control.mesher, control.cancel});
  } catch (const MeshingCancelled&) {
    RunOutput cancelled;
    cancelled.cancelled = true;
    return cancelled;
  }
  if (auto errors = check_against_mesh(spec, coarse, limits); !errors.empty())
    throw CaseException(std::move(errors));
  CaseSpec used = spec;  // the case with the weights as used
  used.weights.length_scale = length_scale(coarse);
  ProblemData<2> data = problem_data<2>(used, coarse);
  if (control.reference) data.reference_displacement = *control.reference;
  const Mesh coarse_mesh = coarse;  // small; for the message of indefinite weights
  // The limit counts the whole run: a user sets it for the answer's latency, not the loop's.
  const Deadline deadline = run_deadline(t0, spec.solver.time_limit_s);
  MeshHierarchy meshes = build_mesh_hierarchy(std::move(coarse), spec.mesh.refinements);
  deadline.check("refining the mesh");  // refinement is a small part of the set-up
  const auto t_mesh = Clock::now();
  RunMemory memory;
  memory.mesh_mib = peak_rss_mib();
  choose_contact_weight<2>(used, meshes, data);
  const CaseSolveObserver observer = solve_observer(control, deadline);
  CaseSolution solution;
  try {
    solution = solve_case_levels(std::move(meshes), data, spec, observer, control.start);
  } catch (const IndefiniteSystemError&) {
    // Positive definiteness failing inside a solver is the user's weights, not a crash.
    throw indefinite(used, build_mesh_hierarchy(coarse_mesh, spec.mesh.refinements), data);
  }
  memory.assembly_mib = solution.assembly_mib;
  memory.hierarchy_mib = solution.hierarchy_mib;
  const Discretization<2>& disc = *solution.disc;
  const AssembledProblem& problem = disc.problem();
  const auto t_solve = Clock::now();

  RunOutput out;
  out.cancelled = solution.report.cancelled;
  if (control.want_vtu)
    out.vtu = write_vtu(disc.assembler(), problem, solution.full, solution.parts, solution.contact,
                        solution.generation,
                        control.vtu_ascii ? VtuEncoding::kAscii : VtuEncoding::kBinary);
  const auto t_end = Clock::now();
  ProblemSize size;
  size.levels = disc.num_levels();
  size.dofs = solution.dofs;
  size.dofs_total = solution.dofs_total;
  size.vertices = disc.meshes().finest().num_vertices();
  size.triangles = disc.meshes().finest().num_triangles();
  RunTiming timing;
  timing.mesh_s = seconds(t0, t_mesh);
  timing.assembly_s = solution.assembly_s;
  // Estimation and refinement between the solves of an adaptive run count as solving.
  timing.solve_s = seconds(t_mesh, t_solve) - solution.assembly_s;
  timing.total_s = seconds(t0, t_end);
  memory.peak_mib = peak_rss_mib();
  out.result =
      result_json(used, solution.report, solution.contact, solution.parts, size, timing, memory);
  if (spec.adaptivity) out.result["adaptivity"] = adaptivity_json(solution, *spec.adaptivity);
  if (spec.accuracy) out.result["accuracy"] = accuracy_json(solution, *spec.accuracy);
  annotate_result(out.result, spec, disc.meshes().finest(), solution.contact,
                  largest_strain(disc.assembler(), problem, solution.full));
  out.solution = std::move(solution.x);
  out.displacement = vertex_displacements(disc.finest_space(), solution.full);
  return out;
}

}  // namespace

int most_solves(const CaseSpec& spec) {
  if (spec.accuracy) return 0;
  const std::size_t points = !spec.load_step_points.empty() ? spec.load_step_points.size() + 1
                             : !spec.sweep_points.empty()   ? spec.sweep_points.size()
                                                            : 1;
  const int per_point = spec.adaptivity ? spec.adaptivity->steps + 1 : 1;
  return static_cast<int>(points) * per_point;
}

RunOutput run_case(const CaseSpec& spec, const RunControl& control, const CaseLimits& limits) {
  // Every solve of every point starts with on_step (solve_case_levels), so counting its calls
  // numbers the solves of the whole run; the series runners need not know.
  RunControl counted = control;
  int solves = 0;
  if (control.on_solve)
    counted.on_step = [&control, &solves, most = most_solves(spec)](int step, long long dofs) {
      if (control.on_step) control.on_step(step, dofs);
      control.on_solve(solves++, most);
    };
  try {
    // One point of either dimension; load steps and sweeps repeat it.
    const auto point = [&limits](const CaseSpec& s, const RunControl& c) {
      return s.dimension == 3 ? run_3d_point(s, c, limits) : run_point(s, c, limits);
    };
    if (!spec.load_step_points.empty()) return run_load_steps(spec, counted, point);
    if (spec.sweep_points.empty()) return point(spec, counted);
    return run_sweep(spec, counted, point);
  } catch (const TimeLimitReached& e) {
    throw TimeLimitReached(e.stage(), time_limit_message(spec, e.stage()));
  } catch (const NonFiniteError& e) {
    throw CaseException({non_finite_problem(e.what())});
  }
}

}  // namespace fosls
