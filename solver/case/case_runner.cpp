#include "case/case_runner.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "assembly/definiteness.hpp"
#include "assembly/discretization.hpp"
#include "case/case_admission.hpp"
#include "case/expression.hpp"
#include "case/mesh_factory.hpp"
#include "core/indefinite_system.hpp"
#include "post/contact_output.hpp"
#include "post/vtu_writer.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// Problems that need the coarse mesh: unknown groups, no Dirichlet group, size limits.
std::vector<CaseError> check_against_mesh(const CaseSpec& spec, const Mesh& mesh,
                                          const CaseLimits& limits) {
  return check_against_groups(spec, mesh.group_names(),
                              unknowns_after_refinement(mesh.num_triangles(), mesh.num_edges(),
                                                        mesh.num_vertices(), spec.mesh.refinements),
                              true, limits);
}

RigidObstacle rigid_obstacle(const Obstacle& o) {
  RigidObstacle r;
  r.kind = o.kind == Obstacle::Kind::kPlane    ? RigidObstacle::Kind::kPlane
           : o.kind == Obstacle::Kind::kCircle ? RigidObstacle::Kind::kCircle
                                               : RigidObstacle::Kind::kGap;
  r.point = o.point, r.normal = o.normal, r.center = o.center, r.radius = o.radius;
  return r;
}

/// The case in the assembly layer's terms.
ProblemData problem_data(const CaseSpec& spec, const Mesh& mesh) {
  ProblemData d;
  d.material = {.mu = spec.material.mu, .lambda = spec.material.lambda};
  const Weights& w = spec.weights;
  d.weights = {.c1 = w.c1, .c2 = w.c2, .c3 = w.c3, .c4 = w.c4};
  for (int i = 0; i < 2; ++i) d.body_force[i] = compile_scalar(spec.body_force[i]);
  d.groups.resize(mesh.group_names().size());  // unnamed groups: traction free
  for (const auto& [name, bc] : spec.boundary) {
    GroupData& g = d.groups[mesh.group_index(name)];
    switch (bc.type) {
      case BoundaryCondition::Type::kDirichlet:
        g.role = GroupRole::kDirichlet;
        break;
      case BoundaryCondition::Type::kNeumann:
        g.role = GroupRole::kNeumann;
        break;
      case BoundaryCondition::Type::kContact:
        g.role = GroupRole::kContact;
        g.contact.obstacle = rigid_obstacle(bc.obstacle);
        g.contact.direction = bc.direction == ContactDirection::kBodyNormal
                                  ? ConstraintDirection::kBodyNormal
                                  : ConstraintDirection::kObstacleNormal;
        if (bc.obstacle.kind == Obstacle::Kind::kGap)
          g.contact.gap = compile_scalar(bc.obstacle.gap);
        break;
    }
    if (bc.type != BoundaryCondition::Type::kContact)
      for (int i = 0; i < 2; ++i) g.values[i] = compile_scalar(bc.values[i]);
  }
  return d;
}

SolverOptions solver_options(const SolverSettings& s) {
  SolverOptions o;
  switch (s.method) {
    case Method::kMmg:
      o.method = SolverMethod::kMmg;
      break;
    case Method::kTnnmg:
      o.method = SolverMethod::kTnnmg;
      break;
    case Method::kPdas:
      o.method = SolverMethod::kPdas;
      break;
    case Method::kPgs:
      o.method = SolverMethod::kPgs;
      break;
  }
  o.tolerance = s.tolerance;
  o.max_iterations = s.max_iterations;
  o.multilevel.smoother =
      s.smoother == SmootherKind::kPatch ? SmootherType::kPatch : SmootherType::kPoint;
  o.multilevel.pre_smoothing = s.pre_smoothing;
  o.multilevel.post_smoothing = s.post_smoothing;
  o.multilevel.projection = s.coarse_obstacle == CoarseObstacle::kA   ? CoarseProjection::kA
                            : s.coarse_obstacle == CoarseObstacle::kB ? CoarseProjection::kB
                                                                      : CoarseProjection::kC;
  return o;
}

CaseException indefinite(const Weights& w) {
  std::ostringstream m;
  m << "the weights c1 = " << w.c1 << ", c2 = " << w.c2 << ", c3 = " << w.c3 << ", c4 = " << w.c4
    << " make the FOSLS matrix indefinite (the contact term c3 is too large relative to c1 and "
       "c2); lower c3 (the default is 0.1) or raise c1 and c2";
  return CaseException("/weights", m.str());
}

nlohmann::json history_json(const std::vector<IterationRecord>& history) {
  nlohmann::json h = nlohmann::json::array();
  for (const auto& r : history)
    h.push_back({{"iteration", r.iteration},
                 {"energy", r.energy},
                 {"correction", r.correction},
                 {"kkt_residual", r.kkt_residual},
                 {"active", r.active},
                 {"changed", r.changed},
                 {"time_s", r.time_s}});
  return h;
}

bool has_contact(const CaseSpec& spec) {
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kContact) return true;
  return false;
}

}  // namespace

std::vector<CaseError> validate_case(const nlohmann::json& j, const CaseReadOptions& options,
                                     const MeshingControl& meshing) {
  CaseReadResult read = read_case(j, options);
  if (!read.errors.empty()) return read.errors;
  try {
    const Mesh mesh = build_coarse_mesh(read.spec->mesh, meshing);
    return check_against_mesh(*read.spec, mesh, options.limits);
  } catch (const CaseException& e) {
    return e.errors();
  }
}

RunOutput run_case(const CaseSpec& spec, const RunControl& control, const CaseLimits& limits) {
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
  ProblemData data = problem_data(spec, coarse);
  MeshHierarchy meshes = build_mesh_hierarchy(std::move(coarse), spec.mesh.refinements);
  const auto t_mesh = Clock::now();
  Discretization disc(std::move(meshes), std::move(data));
  const auto& problem = disc.problem();
  if (has_contact(spec) && !contact_layer_is_definite(disc.finest_space(), problem.qp))
    throw indefinite(spec.weights);
  const SolverOptions options = solver_options(spec.solver);
  const LevelHierarchy hierarchy =
      options.method == SolverMethod::kPdas ? LevelHierarchy{} : disc.build_level_hierarchy();
  const auto t_assembly = Clock::now();

  SolverObserver observer;
  if (control.on_iteration) observer.on_iteration = control.on_iteration;
  if (control.cancel)
    observer.cancelled = [&control] { return control.cancel->load(std::memory_order_relaxed); };
  Vector x;
  SolverReport report;
  try {
    report = solve_box_qp(problem.qp, hierarchy, options, observer, x);
  } catch (const IndefiniteSystemError&) {
    // Positive definiteness failing inside a solver is the user's weights, not a crash.
    throw indefinite(spec.weights);
  }
  const auto t_solve = Clock::now();

  const Vector full = disc.assembler().full_vector(problem, x);
  const FunctionalParts parts = disc.assembler().functional(full);
  const ContactResult contact = contact_output(disc.assembler(), problem, full);

  RunOutput out;
  out.cancelled = report.cancelled;
  nlohmann::json& r = out.result;
  r["name"] = spec.name;
  r["method"] = method_name(options.method);
  r["converged"] = report.converged;
  r["cancelled"] = report.cancelled;
  r["iterations"] = report.iterations;
  r["levels"] = disc.num_levels();
  r["dofs"] = problem.qp.size();
  r["dofs_total"] = disc.finest_space().num_dofs();
  r["vertices"] = disc.meshes().finest().num_vertices();
  r["triangles"] = disc.meshes().finest().num_triangles();
  r["initial_kkt_residual"] = report.initial_kkt;
  r["final_kkt_residual"] = report.final_kkt;
  r["asymptotic_rate"] = report.asymptotic_rate;
  r["active"] = report.active;
  if (!report.message.empty()) r["message"] = report.message;
  r["history"] = history_json(report.history);
  nlohmann::json c;
  std::vector<double> xs, ys, ss, ps, gs;
  std::vector<bool> act;
  for (const auto& e : contact.edges) {
    xs.push_back(e.x), ys.push_back(e.y), ss.push_back(e.s), ps.push_back(e.pressure);
    gs.push_back(e.gap), act.push_back(e.active);
  }
  c["x"] = xs, c["y"] = ys, c["s"] = ss, c["pressure"] = ps, c["gap"] = gs, c["active"] = act;
  c["force"] = {contact.force_x, contact.force_y};
  bool obstacle_normal = false;
  for (const auto& [name, bc] : spec.boundary)
    obstacle_normal |= bc.type == BoundaryCondition::Type::kContact &&
                       bc.direction == ContactDirection::kObstacleNormal;
  c["direction"] = obstacle_normal ? "obstacle_normal" : "body_normal";
  nlohmann::json obstacles = nlohmann::json::object();
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kContact)
      obstacles[name] = bc.obstacle.kind == Obstacle::Kind::kPlane    ? "plane"
                        : bc.obstacle.kind == Obstacle::Kind::kCircle ? "circle"
                                                                      : "gap";
  c["obstacles"] = obstacles;
  r["contact"] = c;
  r["functional"] = {{"total", parts.total()},
                     {"momentum", parts.momentum},
                     {"constitutive", parts.constitutive},
                     {"contact", parts.contact},
                     {"asymmetry", parts.asymmetry},
                     {"units", "stresses scaled by mu"}};
  // What a viewer needs to compare with a reference (e.g. the Hertz radius and moduli).
  r["material"] = {
      {"mu", spec.material.mu},
      {"lambda", spec.material.incompressible() ? nlohmann::json("inf")
                                                : nlohmann::json(spec.material.lambda)}};
  if (spec.mesh.kind == MeshSpec::Kind::kBuiltin)
    r["mesh"] = {{"builtin", spec.mesh.builtin},
                 {"params", spec.mesh.params},
                 {"size", spec.mesh.size},
                 {"refinements", spec.mesh.refinements}};
  r["weights"] = {{"c1", spec.weights.c1},
                  {"c2", spec.weights.c2},
                  {"c3", spec.weights.c3},
                  {"c4", spec.weights.c4}};
  nlohmann::json warnings = nlohmann::json::array();
  if (!report.converged && !report.cancelled) warnings.push_back(report.message);
  if (report.cycle.safeguard_reductions > 0)
    warnings.push_back("coarse corrections were shortened " +
                       std::to_string(report.cycle.safeguard_reductions) +
                       " times to stay feasible (curved contact boundary)");
  r["warnings"] = warnings;
  if (control.want_vtu) out.vtu = write_vtu(disc.assembler(), problem, full, parts);
  const auto t_end = Clock::now();
  r["timing"] = {{"mesh_s", seconds(t0, t_mesh)},
                 {"assembly_s", seconds(t_mesh, t_assembly)},
                 {"setup_s", report.setup_s},
                 {"solve_s", seconds(t_assembly, t_solve)},
                 {"total_s", seconds(t0, t_end)}};
  return out;
}

}  // namespace fosls
