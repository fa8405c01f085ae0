// The `boundary` section: a condition per boundary group (dirichlet, neumann, pressure, contact;
// the contact condition and its obstacle in obstacle_section.cpp). Also the vectors of scalars
// that conditions and the body force share.

#include <algorithm>

#include "case/format/case_sections.hpp"
#include "case/format/rule_checker.hpp"

namespace fosls {

namespace {

using nlohmann::json;

ObjectRulePtr condition_rule(const CaseReadOptions& options, int dim) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "a boundary condition";
  r->anchor = "condition";
  r->discriminator = "type";
  r->discriminator_meaning = "dirichlet, neumann, pressure or contact";
  const std::size_t length = options.limits.max_expression_length;
  const ValueRule scalar = scalar_value_in(dim, length);
  const std::string of_xy = in_dimension(dim, "x and y", "x, y and z");
  const ValueRule component =
      one_of_value({scalar, null_value()}, "a number, an expression of " + of_xy + ", or null");
  r->variants = {
      {"dirichlet",
       "a dirichlet condition",
       "prescribed displacement",
       {required_field(
           "displacement",
           vector_value(dim, component, "an array of 2 numbers, expressions or null",
                        "an array of 3 numbers, expressions or null"),
           "the prescribed displacement " + in_dimension(dim, "[u_x, u_y]", "[u_x, u_y, u_z]") +
               "; null leaves that component free with zero traction (a roller or "
               "symmetry plane: " +
               in_dimension(dim, "[0, null]", "[0, null, null]") + " on a plane x = const)")},
       // [0, null] is a roller; [null, null] would prescribe nothing.
       some_displacement_prescribed(
           in_dimension(dim, "both components are null", "all three components are null") +
           ", which prescribes nothing; a boundary free in " +
           in_dimension(dim, "both directions", "every direction") +
           " is a neumann condition with traction " + in_dimension(dim, "[0, 0]", "[0, 0, 0]")),
       in_dimension(dim, "not both components null", "not all three components null")},
      {"neumann",
       "a neumann condition",
       "prescribed traction σn",
       {required_field(
           "traction", scalars_value(options, dim),
           "the prescribed traction " + in_dimension(dim, "[t_x, t_y]", "[t_x, t_y, t_z]"))},
       {},
       ""},
      {"pressure",
       "a pressure condition",
       "a normal pressure: the traction t = −p n with the body's outward normal n",
       {required_field("pressure", scalar,
                       "the pressure p: a number or an expression of " + of_xy +
                           "; p > 0 pushes into the body")},
       {},
       ""},
      contact_variant(options, dim),
  };
  return r;
}

BoundaryCondition read_condition(const json& j) {
  BoundaryCondition bc;
  const std::string type = j["type"];
  if (type == "dirichlet") {
    bc.type = BoundaryCondition::Type::kDirichlet;
    const json& u = j["displacement"];
    for (std::size_t c = 0; c < u.size(); ++c) {
      bc.prescribed[c] = !u[c].is_null();
      if (bc.prescribed[c]) bc.values[c] = read_scalar(u[c]);
    }
  } else if (type == "neumann") {
    bc.type = BoundaryCondition::Type::kNeumann;
    bc.values = read_scalars(j["traction"]);
  } else if (type == "pressure") {
    bc.type = BoundaryCondition::Type::kPressure;
    bc.values[0] = read_scalar(j["pressure"]);
  } else {
    bc.type = BoundaryCondition::Type::kContact;
    bc.obstacle = read_obstacle(j);
    if (j.value("direction", "body_normal") == "obstacle_normal")
      bc.direction = ContactDirection::kObstacleNormal;
    if (j.contains("friction")) {
      const json& f = j["friction"];
      bc.friction_coefficient = f.value("coefficient", 0.0);
      if (f.contains("bound")) bc.friction_bound = read_scalar(f["bound"]);
    }
  }
  return bc;
}

}  // namespace

ObjectHook some_displacement_prescribed(std::string why) {
  return [why = std::move(why)](const json& j, const std::string& pointer, RuleChecker& checker) {
    if (!j.contains("displacement") || !checker.usable(j, pointer, {"displacement"})) return;
    const json& u = j["displacement"];
    if (std::all_of(u.begin(), u.end(), [](const json& c) { return c.is_null(); }))
      checker.error(child_pointer(pointer, "displacement"), why);
  };
}

ValueRule scalars_value(const CaseReadOptions& options, int dim) {
  return vector_value(dim, scalar_value_in(dim, options.limits.max_expression_length),
                      "an array of 2 numbers or expressions of x and y",
                      "an array of 3 numbers or expressions of x, y and z");
}

Scalar read_scalar(const json& j) {
  Scalar s;
  if (j.is_number())
    s.value = j.get<double>();
  else
    s.expression = j.get<std::string>();
  return s;
}

Point read_point(const json& j) { return {j[0].get<double>(), j[1].get<double>()}; }

std::array<Scalar, 3> read_scalars(const json& j) {
  std::array<Scalar, 3> s;
  for (std::size_t c = 0; c < j.size() && c < 3; ++c) s[c] = read_scalar(j[c]);
  return s;
}

ValueRule boundary_rule(const CaseReadOptions& options, int dim) {
  return map_value(name_value(options.limits.max_name_length, "the boundary group name"),
                   object_value(condition_rule(options, dim)), options.limits.max_geometry_entities,
                   "object mapping boundary group names to conditions", "conditions");
}

std::map<std::string, BoundaryCondition> read_boundary_section(const json& j) {
  std::map<std::string, BoundaryCondition> boundary;
  for (const auto& [name, condition] : j.items()) boundary[name] = read_condition(condition);
  return boundary;
}

}  // namespace fosls
