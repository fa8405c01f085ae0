#include "case/format/case_reader.hpp"

#include <algorithm>
#include <optional>

#include "case/admission/early_group_check.hpp"
#include "case/format/case_sections.hpp"
#include "case/format/dimension_support.hpp"
#include "case/format/rule_checker.hpp"
#include "case/format/units.hpp"
#include "strategy/force_accuracy.hpp"

namespace fosls {

ObjectRulePtr case_rule(const CaseReadOptions& options, int dim) {
  const CaseSpec defaults;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the case";
  r->anchor = "case";
  const nlohmann::json no_force =
      dim == 3 ? nlohmann::json::array({0, 0, 0}) : nlohmann::json::array({0, 0});
  r->fields = {
      optional_field("name", name_value(options.limits.max_name_length, "the name"), defaults.name,
                     "a label copied to the result"),
      optional_field("units", object_value(units_rule()), nullptr,
                     "the units the case's numbers are in, named in the outputs (absent: not "
                     "declared; the numbers are used as they are either way)"),
      optional_field("dimension", integer_value(Range::closed(2, 3)), 2,
                     "2: a plane-strain body of triangles; 3: a body of tetrahedra (\"3D "
                     "cases\"), whose vectors have three components"),
      required_field("mesh", object_value(mesh_rule(options, dim)), "the mesh of the body"),
      required_field("material", object_value(material_rule()),
                     "the material (mu and lambda, or E and nu)"),
      optional_field("body_force", scalars_value(options, dim), dim == 0 ? nullptr : no_force,
                     "volume force f = " + in_dimension(dim, "[f_x, f_y]", "[f_x, f_y, f_z]") +
                         (dim == 0 ? "; absent: zero" : "")),
      required_field("boundary", boundary_rule(options, dim),
                     "the conditions on the boundary groups"),
      optional_field("weights", object_value(weights_rule()), nullptr,
                     "weights of the least-squares functional"),
      optional_field("solver", object_value(solver_rule()), nullptr,
                     "the iteration and its parameters"),
      optional_field("adaptivity", object_value(adaptivity_rule(options)), nullptr,
                     "adaptive refinement driven by the functional (absent: uniform refinement "
                     "only)"),
      optional_field("accuracy", object_value(accuracy_rule(options)), nullptr,
                     "the contact force to a requested relative error: uniform refinement from "
                     "mesh.refinements until the estimated error is below it (absent: the "
                     "levels of mesh.refinements only)"),
      optional_field("load_steps", load_steps_rule(options), nullptr,
                     "quasi-static steps after the case as given: each an object of JSON pointers "
                     "and their new values, applied to the case as the previous step left it and "
                     "solved from the previous step's state; friction acts on each step's slip"),
      optional_field("sweep", object_value(sweep_rule(options)), nullptr,
                     "a number of the case that takes several values, solved in order with "
                     "continuation"),
  };
  return r;
}

int case_dimension(const nlohmann::json& j) {
  return j.is_object() && j.contains("dimension") && j["dimension"].is_number() &&
                 j["dimension"] == 3
             ? 3
             : 2;
}

namespace {

/// What friction is not (yet) combined with (docs/method.md §8.5).
void check_friction_support(const CaseSpec& spec, std::vector<CaseError>& errors) {
  if (!has_friction(spec)) return;
  if (spec.solver.method == SolverMethod::kTnnmg)
    errors.push_back(
        {"/solver/method", "tnnmg does not handle friction; use mmg (the default) or pdas"});
  if (spec.adaptivity)
    errors.push_back({"/adaptivity",
                      "adaptive refinement is not available with friction yet; refine "
                      "uniformly with mesh.refinements"});
}

/// What the accuracy loop is not combined with (it chooses the levels itself), and that it
/// asks for a contact force.
void check_accuracy_support(const nlohmann::json& j, const CaseSpec& spec,
                            std::vector<CaseError>& errors) {
  if (!j.contains("accuracy")) return;
  if (!has_contact(spec))
    errors.push_back({"/accuracy",
                      "accuracy is asked of the contact force, and the case has no contact "
                      "condition; refine with mesh.refinements instead"});
  for (const char* other : {"adaptivity", "load_steps", "sweep"})
    if (j.contains(other))
      errors.push_back({"/accuracy", std::string("accuracy cannot be combined with ") + other +
                                         " yet; remove one of the two"});
}

/// What the order-2 space is not built for yet (docs/case-format.md, "Order 2").
void check_order2_support(const nlohmann::json& j, const CaseSpec& spec,
                          std::vector<CaseError>& errors) {
  if (spec.mesh.order != 2) return;
  auto refuse = [&errors](const std::string& what) {
    errors.push_back({"/mesh/order", "order 2 " + what + "; use mesh.order 1 for this case"});
  };
  for (const auto& [name, bc] : spec.boundary) {
    if (bc.type != BoundaryCondition::Type::kContact) continue;
    if (bc.frictional()) refuse("is frictionless only (boundary." + name + " has friction)");
    if (bc.direction == ContactDirection::kObstacleNormal)
      refuse("constrains along the body normal only (boundary." + name +
             ".direction is obstacle_normal)");
  }
  for (const char* other : {"adaptivity", "load_steps"})
    if (j.contains(other)) refuse(std::string("cannot be combined with ") + other + " yet");
  if (spec.solver.method != SolverMethod::kMmg && spec.solver.method != SolverMethod::kPdas)
    refuse("is solved by mmg or pdas only (solver.method)");
}

std::vector<CaseError> rule_problems(const nlohmann::json& j, const CaseReadOptions& options,
                                     int dim) {
  RuleChecker checker(options);
  checker.check_object(j, *case_rule(options, dim), "");
  return checker.take_errors();
}

/// A case without "dimension" that the 3D rules take better than the 2D ones is a 3D case whose
/// dimension was left out: one sentence at /dimension, then its problems as a 3D case, rather
/// than every 3-vector refused as a 2D one.
std::optional<std::vector<CaseError>> problems_as_3d(const nlohmann::json& j,
                                                     const CaseReadOptions& options,
                                                     const std::vector<CaseError>& as_2d) {
  const bool looks_3d = std::any_of(as_2d.begin(), as_2d.end(), [](const CaseError& e) {
    return e.detail.find(kNeedsDimension3) != std::string::npos;
  });
  if (!looks_3d) return std::nullopt;
  std::vector<CaseError> as_3d = rule_problems(j, options, 3);
  if (as_3d.size() >= as_2d.size()) return std::nullopt;
  as_3d.insert(as_3d.begin(),
               {"/dimension",
                std::string("missing: the case has 3D data (3-component vectors or a 3D builtin), "
                            "which a 2D case refuses; ") +
                    kNeedsDimension3});
  return as_3d;
}

}  // namespace

CaseReadResult read_case(const nlohmann::json& j, const CaseReadOptions& options) {
  CaseReadResult result;
  if (!j.is_object()) {
    result.errors.push_back(
        {"", "the case must be a JSON object with the fields mesh, material and boundary, got " +
                 describe_value(j)});
    return result;
  }
  const int dim = case_dimension(j);
  result.errors = rule_problems(j, options, dim);
  if (!result.errors.empty()) {
    if (dim == 2 && !j.contains("dimension"))
      if (auto as_3d = problems_as_3d(j, options, result.errors)) {
        result.errors = std::move(*as_3d);
        return result;
      }
    if (dim == 2) add_unknown_group_problems(j, options, result.errors);  // in one round
    return result;
  }

  CaseSpec spec;
  spec.name = j.value("name", spec.name);
  spec.dimension = dim;
  if (j.contains("units")) spec.units = read_units_section(j["units"]);
  spec.mesh = read_mesh_section(j["mesh"]);
  spec.material = read_material_section(j["material"]);
  if (j.contains("body_force")) spec.body_force = read_scalars(j["body_force"]);
  spec.boundary = read_boundary_section(j["boundary"]);
  if (j.contains("weights")) spec.weights = read_weights_section(j["weights"]);
  if (j.contains("solver")) spec.solver = read_solver_section(j["solver"]);
  if (j.contains("adaptivity"))
    spec.adaptivity = read_adaptivity_section(j["adaptivity"], options.limits);
  if (j.contains("accuracy")) spec.accuracy = read_accuracy_section(j["accuracy"], options.limits);
  // An adaptive (or accuracy) step's solution only decides where to refine (whether to) and
  // where the next step starts: iterating it beyond its discretisation error is wasted, so that
  // is where its solve stops unless the case gives a tolerance (docs/method.md §5.1).
  const auto solver_gives = [&j](const char* key) {
    return j.contains("solver") && j["solver"].contains(key);
  };
  // 3D keeps its number: its discretisation rule is refused for now (dimension_support.cpp).
  if ((spec.adaptivity || spec.accuracy) && !solver_gives("tolerance") && spec.dimension == 2)
    spec.solver.stopping = StoppingRule::kDiscretisation;
  if (spec.accuracy && !solver_gives("discretisation_fraction"))
    spec.solver.discretisation_fraction = kAccuracyDiscretisationFraction;
  check_friction_support(spec, result.errors);
  check_accuracy_support(j, spec, result.errors);
  settle_accuracy_refinement(spec, result.errors);
  check_order2_support(j, spec, result.errors);
  for (CaseError& e : dimension_support_problems(j, spec)) result.errors.push_back(std::move(e));
  if (!result.errors.empty()) return result;
  if (j.contains("load_steps")) {
    read_load_steps_section(j, options, spec, result.errors);
    if (!result.errors.empty()) return result;
  }
  if (j.contains("sweep")) {
    read_sweep_section(j, options, spec, result.errors);
    if (!result.errors.empty()) return result;
  }
  result.spec = std::move(spec);
  return result;
}

}  // namespace fosls
