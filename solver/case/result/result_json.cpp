#include "case/result/result_json.hpp"

#include <cmath>
#include <sstream>

#include "case/format/solver_methods.hpp"
#include "case/result/obstacle_gap.hpp"
#include "post/stick_front.hpp"
#include "solvers/rounding_level_stop.hpp"

namespace fosls {

namespace {

using nlohmann::json;

std::string short_number(double v) { return sentence_number(v, 3); }

/// The constraint's direction and each contact group's obstacle, in both dimensions.
void add_constraint_json(json& c, const CaseSpec& spec) {
  bool obstacle_normal = false;
  json obstacles = json::object();
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kContact) {
      obstacle_normal |= bc.direction == ContactDirection::kObstacleNormal;
      // The type's name; a gap function is "gap" here, "obstacle" in sentences.
      obstacles[name] = bc.obstacle.kind == Obstacle::Kind::kGap
                            ? "gap"
                            : obstacle_noun(bc.obstacle, spec.dimension);
    }
  c["direction"] = obstacle_normal ? "obstacle_normal" : "body_normal";
  c["obstacles"] = obstacles;
}

/// The friction laws and, for Coulomb, the updates of the slip bounds; null without friction.
json friction_json(const CaseSpec& spec, const SolverReport& report) {
  json groups = json::object();
  for (const auto& [name, bc] : spec.boundary)
    if (bc.type == BoundaryCondition::Type::kContact && bc.frictional())
      groups[name] = bc.friction_coefficient > 0
                         ? json{{"law", "coulomb"}, {"coefficient", bc.friction_coefficient}}
                         : json{{"law", "tresca"}, {"coefficient", nullptr}};
  if (groups.empty()) return nullptr;
  const std::vector<double>& c = report.update_changes;
  // The mean factor by which successive updates shrank, from the second update on (the first
  // sets the bounds from S_n = 0).
  json contraction = nullptr;
  if (c.size() >= 3 && c[1] > 0 && c.back() > 0)
    contraction = std::pow(c.back() / c[1], 1.0 / static_cast<double>(c.size() - 2));
  return {{"groups", groups},
          {"updates", c.size()},
          {"update_changes", c},
          {"contraction", contraction},
          {"last_change", c.empty() ? json(nullptr) : json(c.back())},
          {"fallback_after", report.switched_at > 0 ? json(report.switched_at) : json(nullptr)}};
}

json mesh_json(const MeshSpec& mesh) {
  static const char* const kSources[] = {"builtin", "geometry", "msh", "geo_file"};
  json m = {{"source", mesh.msh_path.empty() ? kSources[static_cast<int>(mesh.kind)] : "msh_file"},
            {"size", mesh.size},
            {"refinements", mesh.refinements},
            {"order", mesh.order}};
  // What a viewer needs to compare with a reference (e.g. the Hertz radius).
  if (mesh.kind == MeshSpec::Kind::kBuiltin) {
    m["builtin"] = mesh.builtin;
    if (!mesh.params.empty()) m["params"] = mesh.params;  // a 3D builtin has none by default
  }
  return m;
}

json stopping_json(const SolverReport& report, const SolverOptions& options) {
  const char* converged_by = converged_by_name(report.converged_by);
  return {{"rule",
           options.stopping == StoppingRule::kDiscretisation ? "discretisation" : "kkt_residual"},
          {"fraction", options.discretisation_fraction},
          {"converged_by", converged_by},
          {"algebraic_error",
           std::isfinite(report.algebraic_error) ? json(report.algebraic_error) : json()},
          {"estimator", report.estimator}};
}

}  // namespace

json contact_json(const ContactResult& contact) {
  json c;
  std::vector<double> xs, ys, ss, ls, ps, gs, shear, slip;
  std::vector<bool> active;
  std::vector<std::string> state;
  for (const auto& e : contact.edges) {
    xs.push_back(e.x), ys.push_back(e.y), ss.push_back(e.s), ls.push_back(e.length);
    ps.push_back(e.pressure), gs.push_back(e.gap), active.push_back(e.active);
    shear.push_back(e.shear), slip.push_back(e.slip), state.push_back(state_name(e.state));
  }
  c["x"] = xs, c["y"] = ys, c["s"] = ss, c["length"] = ls;
  c["pressure"] = ps, c["gap"] = gs, c["active"] = active;
  c["shear"] = shear, c["slip"] = slip, c["state"] = state;
  const ContactZone stick = contact.stick_zone();
  c["stick_zone"] = {{"edges", stick.edges},
                     {"length", stick.length},
                     {"s_start", stick.edges ? json(stick.s_start) : json(nullptr)},
                     {"s_end", stick.edges ? json(stick.s_end) : json(nullptr)}};
  if (contact.frictional) {
    c["stick_zone"]["slipping_below_bound"] = contact.slipping_below_bound;
    c["stick_zone"]["sticking_at_bound"] = contact.sticking_at_bound;
    const StickFronts fronts = locate_stick_fronts(contact.edges);
    c["stick_zone"]["front_start"] = stick.edges ? json(fronts.start) : json(nullptr);
    c["stick_zone"]["front_end"] = stick.edges ? json(fronts.end) : json(nullptr);
    c["stick_zone"]["width"] = fronts.width;
  }
  c["force"] = {contact.force_x, contact.force_y};
  const ContactZone z = contact.zone();
  c["zone"] = {{"edges", z.edges},
               {"length", z.length},
               {"s_start", z.edges ? json(z.s_start) : json(nullptr)},
               {"s_end", z.edges ? json(z.s_end) : json(nullptr)},
               {"peak_pressure", z.peak_pressure},
               {"peak_location", z.edges ? json({z.peak_x, z.peak_y}) : json(nullptr)}};
  return c;
}

StopReason stop_reason(const SolverReport& report) {
  if (report.converged) return StopReason::kConverged;
  if (report.cancelled) return StopReason::kCancelled;
  return report.time_limited ? StopReason::kTimeLimit : StopReason::kMaxIterations;
}

namespace {

/// The KKT residual at the end over the initial one (0 when the start was already exact).
double relative_kkt(const SolverReport& report) {
  return report.initial_kkt > 0 ? report.final_kkt / report.initial_kkt : 0.0;
}

/// Why a solve stopped without converging, with the numbers and what to change; empty when it
/// converged.
std::string convergence_message(const SolverReport& report, const SolverOptions& options) {
  switch (stop_reason(report)) {
    case StopReason::kConverged:
      return "";
    case StopReason::kCancelled:
      return "cancelled after " + std::to_string(report.iterations) + " iterations";
    case StopReason::kTimeLimit:
      return "not converged: solver.time_limit_s (" + short_number(options.time_limit_s) +
             " s) ran out after " + std::to_string(report.iterations) +
             " iterations, with the KKT residual at " + short_number(relative_kkt(report)) +
             " of its initial value (tolerance " + short_number(options.tolerance) +
             "). The result is the last iterate: raise solver.time_limit_s, or use a coarser "
             "mesh or a faster solver.method";
    case StopReason::kMaxIterations:
      break;
  }
  return "not converged: after " + std::to_string(report.iterations) +
         " iterations (solver.max_iterations) the KKT residual had fallen to " +
         short_number(relative_kkt(report)) + " of its initial value, not to the tolerance " +
         short_number(options.tolerance) + " (solver.tolerance); the last iterations reduced " +
         "it by a factor " + short_number(report.asymptotic_rate) +
         " each. The result is the last iterate: raise solver.max_iterations, or check the "
         "case (a too fine mesh for the method, or a contact zone the mesh does not resolve)";
}

/// The result's `history`: iteration 0 and every iteration after it.
json history_json(const std::vector<IterationRecord>& history) {
  json h = json::array();
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

/// The result's `solver_statistics`: counts and times of the multilevel method's parts.
json statistics_json(const SolverReport& report) {
  const CycleStatistics& c = report.cycle;
  return {{"nested_iterations", report.nested_iterations},
          {"nested_s", report.nested_s},
          {"accelerated_steps", report.accelerated_steps},
          {"galerkin_rebuilds", c.galerkin_rebuilds},
          {"safeguard_reductions", c.safeguard_reductions},
          {"double_precision_smoothers", c.double_precision_smoothers},
          {"galerkin_s", c.galerkin_s},
          {"smoothing_s", c.smoothing_s},
          {"strip_s", c.strip_s},
          {"coarse_s", c.coarse_s}};
}

/// The solver's warnings of a result, each saying what happened and what it means.
std::vector<ResultWarning> result_warnings(const SolverReport& report,
                                           const SolverOptions& options) {
  std::vector<ResultWarning> warnings;
  if (const StopReason why = stop_reason(report);
      why == StopReason::kMaxIterations || why == StopReason::kTimeLimit)
    warnings.push_back({why == StopReason::kTimeLimit ? "time_limit" : "not_converged",
                        convergence_message(report, options)});
  if (report.converged_by == ConvergedBy::kRoundingLevel)
    warnings.push_back(
        {"rounding_level",
         "the KKT residual stopped falling at " + short_number(relative_kkt(report)) +
             " of its initial value, within " + short_number(kRoundingLevelFactor) +
             " times the level that rounding allows, before the tolerance " +
             short_number(options.tolerance) +
             " (solver.tolerance); the solve stopped there as converged (docs/method.md §5.2). "
             "Either the start was already close to the solution (an adaptive step's or a sweep "
             "point's), or the tolerance is probably below what double precision can show for this "
             "problem"});
  if (report.switched_at > 0)
    warnings.push_back({"coulomb_fallback",
                        "mmg's Coulomb iteration stalled after " +
                            std::to_string(report.switched_at) +
                            " iterations; pdas (a direct factorisation) finished the solve from "
                            "there (friction.fallback_after; docs/method.md §8.4)"});
  if (report.cycle.safeguard_reductions > 0)
    warnings.push_back(
        {"coarse_corrections_shortened",
         "coarse corrections were shortened " + std::to_string(report.cycle.safeguard_reductions) +
             " times to stay feasible: on a curved contact boundary the coarse levels' contact "
             "normals differ from the finest level's, so a coarse correction can overshoot the "
             "obstacle and is cut back. This is expected there and needs no action: it costs "
             "convergence speed, not accuracy"});
  return warnings;
}

/// The result's `weights` object: the weights as used, in both dimensions.
json weights_json(const Weights& w) {
  return {{"c1", w.c1},
          {"c2", w.c2},
          {"c3", w.c3},
          {"c4", w.c4},
          {"c2_volumetric", w.c2_volumetric},
          {"c3_rule", w.c3_auto ? "auto" : "given"},
          {"c3_limit", w.c3_limit > 0 ? json(w.c3_limit) : json()},
          {"length_scale", w.length_scale}};
}

}  // namespace

json result_json(const CaseSpec& spec, const SolverReport& report, json contact,
                 const FunctionalParts& functional, const ProblemSize& size,
                 const RunTiming& timing, const RunMemory& memory) {
  const SolverOptions& options = spec.solver;
  json r;
  r["name"] = spec.name;
  r["method"] = method_info(options.method).name;
  r["converged"] = report.converged;
  r["stop_reason"] = stop_reason_name(stop_reason(report));
  r["cancelled"] = report.cancelled;
  r["iterations"] = report.iterations;
  r["tolerance"] = options.tolerance;
  r["stopping"] = stopping_json(report, options);
  r["levels"] = size.levels;
  r["dofs"] = size.dofs;
  r["dofs_total"] = size.dofs_total;
  r["vertices"] = size.vertices;
  r[spec.dimension == 3 ? "tetrahedra" : "triangles"] = size.cells;
  if (spec.dimension == 3) r["dimension"] = 3;  // absent: 2, as in the case
  r["initial_kkt_residual"] = report.initial_kkt;
  r["final_kkt_residual"] = report.final_kkt;
  r["relative_kkt_residual"] = relative_kkt(report);
  r["asymptotic_rate"] = report.asymptotic_rate;
  r["active_bounds"] = report.active;
  r["active"] = report.active;
  if (const std::string m = convergence_message(report, options); !m.empty()) r["message"] = m;
  add_warnings(r, result_warnings(report, options));
  r["history"] = history_json(report.history);
  r["solver_statistics"] = statistics_json(report);
  add_constraint_json(contact, spec);
  r["contact"] = std::move(contact);
  r["functional"] = {{"total", functional.total()},
                     {"momentum", functional.momentum},
                     {"constitutive", functional.constitutive},
                     {"contact", functional.contact},
                     {"asymmetry", functional.asymmetry},
                     {"friction", functional.friction},
                     {"estimator", std::sqrt(std::max(0.0, functional.total()))},
                     {"units", "stresses scaled by mu"}};
  if (json f = friction_json(spec, report); !f.is_null()) r["friction"] = std::move(f);
  r["material"] = {
      {"mu", spec.material.mu},
      {"lambda", spec.material.incompressible() ? json("inf") : json(spec.material.lambda)}};
  r["mesh"] = mesh_json(spec.mesh);
  r["weights"] = weights_json(spec.weights);
  r["timing"] = {{"mesh_s", timing.mesh_s},
                 {"assembly_s", timing.assembly_s},
                 {"setup_s", report.setup_s},
                 {"solve_s", timing.solve_s},
                 {"total_s", timing.total_s}};
  r["memory"] = {{"mesh_mib", memory.mesh_mib},
                 {"assembly_mib", memory.assembly_mib},
                 {"hierarchy_mib", memory.hierarchy_mib},
                 {"chain_mib", report.chain_mib > 0 ? report.chain_mib : memory.hierarchy_mib},
                 {"setup_mib", report.setup_mib > 0 ? report.setup_mib : memory.hierarchy_mib},
                 {"peak_mib", memory.peak_mib}};
  return r;
}

}  // namespace fosls
