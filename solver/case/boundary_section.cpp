// The `boundary` section: a condition per boundary group (dirichlet, neumann, pressure, contact),
// and the obstacles of contact conditions. Also the scalars [a, b] that conditions and the body
// force share.

#include <algorithm>

#include "case/case_sections.hpp"
#include "case/rule_checker.hpp"

namespace fosls {

namespace {

using nlohmann::json;

/// A plane's normal gives its orientation, so it cannot be zero.
void check_plane(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!checker.usable(j, pointer, {"normal"}) || !j.contains("normal")) return;
  if (read_point(j["normal"]).norm() == 0.0)
    checker.error(child_pointer(pointer, "normal"), "the normal is zero; give a non-zero vector");
}

/// The obstacle's normal is needed to constrain the displacement along it.
void check_direction(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!j.contains("direction") || !j.contains("obstacle") ||
      !checker.usable(j, pointer, {"obstacle", "direction"}))
    return;
  if (j["direction"] == "obstacle_normal" && j["obstacle"]["type"] == "gap")
    checker.error(child_pointer(pointer, "direction"),
                  "direction obstacle_normal needs a plane or circle obstacle; a gap obstacle has "
                  "no normal of its own (use body_normal)");
}

/// A rigid-body motion of a plane or circle obstacle, so that an indentation is a case field
/// (and a sweep parameter) rather than a change of the body's Dirichlet data.
FieldRule obstacle_displacement_field() {
  return optional_field("displacement", point_value(), json::array({0, 0}),
                        "rigid displacement [dx, dy] of the obstacle from where point/center "
                        "put it; [0, 0.01] moves it 0.01 up, into a body above it");
}

ObjectRulePtr obstacle_rule(const CaseReadOptions& options) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "an obstacle";
  r->anchor = "obstacle";
  r->discriminator = "type";
  r->discriminator_meaning = "plane, circle or gap";
  r->variants = {
      {"plane",
       "a plane obstacle",
       "a rigid half plane; the gap is the distance to it",
       {required_field("point", point_value(), "a point [x, y] on the plane"),
        required_field("normal", point_value(),
                       "the normal [nx, ny] from the obstacle into the body (any non-zero "
                       "length; it is normalised)"),
        obstacle_displacement_field()},
       check_plane,
       "the normal is not zero"},
      {"circle",
       "a circle obstacle",
       "a rigid disk; the body lies outside it; the gap is the distance to the circle",
       {required_field("center", point_value(), "the centre [x, y] of the circle"),
        required_field("radius", number_value(Range::positive()), "the radius of the circle"),
        obstacle_displacement_field()},
       {},
       ""},
      {"gap",
       "a gap obstacle",
       "the gap g(x, y) itself, measured along the body normal",
       {required_field("g", scalar_value(options.limits.max_expression_length),
                       "the gap g(x, y): a number or an expression of x and y")},
       {},
       ""},
  };
  return r;
}

/// Tresca's bound: a number must be >= 0 now; an expression is checked where it is evaluated.
ValueRule slip_bound_value(std::size_t max_expression_length) {
  ValueRule v = scalar_value(max_expression_length);
  v.hook = [](const json& value, const std::string& pointer, RuleChecker& checker) {
    if (!value.is_number() || value.get<double>() >= 0.0) return true;
    checker.error(pointer, "the slip bound is " + value.dump() + "; it must be >= 0");
    return false;
  };
  v.notes = "a number must be >= 0";
  return v;
}

ObjectRulePtr friction_rule(const CaseReadOptions& options) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "the friction law";
  r->anchor = "friction";
  r->fields = {
      optional_field("coefficient", number_value(Range::closed(0, 10)), nullptr,
                     "Coulomb's coefficient 𝔣: |σ_nt| ≤ 𝔣 |σ_nn|; 0 is frictionless"),
      optional_field("bound", slip_bound_value(options.limits.max_expression_length), nullptr,
                     "Tresca's slip bound s ≥ 0 in stress units, a number or an expression of "
                     "x and y: |σ_nt| ≤ s"),
  };
  r->exclusive = {{{{"coefficient"}, {"bound"}},
                   "give the Coulomb coefficient or the Tresca bound",
                   "give either the Coulomb coefficient or the Tresca bound, not {given}"}};
  r->notes =
      "a bound given as an expression must be >= 0 on the contact boundary (checked "
      "when the case runs)";
  return r;
}

ObjectRulePtr condition_rule(const CaseReadOptions& options) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "a boundary condition";
  r->anchor = "condition";
  r->discriminator = "type";
  r->discriminator_meaning = "dirichlet, neumann, pressure or contact";
  const ValueRule pair = scalar_pair_value(options);
  r->variants = {
      {"dirichlet",
       "a dirichlet condition",
       "prescribed displacement",
       {required_field(
           "displacement",
           tuple_value(
               one_of_value({scalar_value(options.limits.max_expression_length), null_value()},
                            "a number, an expression of x and y, or null"),
               2, "an array of 2 numbers, expressions or null"),
           "the prescribed displacement [u_x, u_y]; null leaves that component free with zero "
           "traction (a roller or symmetry plane: [0, null] on a plane x = const)")},
       // [0, null] is a roller; [null, null] would prescribe nothing.
       some_displacement_prescribed(
           "both components are null, which prescribes nothing; a boundary free in both "
           "directions is a neumann condition with traction [0, 0]"),
       "not both components null"},
      {"neumann",
       "a neumann condition",
       "prescribed traction σn",
       {required_field("traction", pair, "the prescribed traction [t_x, t_y]")},
       {},
       ""},
      {"pressure",
       "a pressure condition",
       "a normal pressure: the traction t = −p n with the body's outward normal n",
       {required_field("pressure", scalar_value(options.limits.max_expression_length),
                       "the pressure p: a number or an expression of x and y; p > 0 pushes "
                       "into the body")},
       {},
       ""},
      {"contact",
       "a contact condition",
       "contact with a rigid obstacle, frictionless unless `friction` is given",
       {required_field("obstacle", object_value(obstacle_rule(options)), "a plane, circle or gap"),
        optional_field("friction", object_value(friction_rule(options)), nullptr,
                       "Coulomb or Tresca friction (docs/method.md §8); absent: frictionless"),
        optional_field("direction", choice_value({"body_normal", "obstacle_normal"}), "body_normal",
                       "the constrained displacement component: u·n with the body's normal, "
                       "or u·ν with the obstacle's normal")},
       check_direction,
       "obstacle_normal needs a plane or circle obstacle"},
  };
  return r;
}

Obstacle read_obstacle(const json& j) {
  Obstacle o;
  const std::string type = j["type"];
  const Point moved = j.contains("displacement") ? read_point(j["displacement"]) : Point::Zero();
  o.displacement = moved;
  if (type == "plane") {
    o.kind = Obstacle::Kind::kPlane;
    o.point = read_point(j["point"]) + moved;
    o.normal = read_point(j["normal"]).normalized();
  } else if (type == "circle") {
    o.kind = Obstacle::Kind::kCircle;
    o.center = read_point(j["center"]) + moved;
    o.radius = j["radius"].get<double>();
  } else {
    o.kind = Obstacle::Kind::kGap;
    o.gap = read_scalar(j["g"]);
  }
  return o;
}

BoundaryCondition read_condition(const json& j) {
  BoundaryCondition bc;
  const std::string type = j["type"];
  if (type == "dirichlet") {
    bc.type = BoundaryCondition::Type::kDirichlet;
    for (int c = 0; c < 2; ++c) {
      bc.prescribed[c] = !j["displacement"][c].is_null();
      if (bc.prescribed[c]) bc.values[c] = read_scalar(j["displacement"][c]);
    }
  } else if (type == "neumann") {
    bc.type = BoundaryCondition::Type::kNeumann;
    bc.values = read_scalar_pair(j["traction"]);
  } else if (type == "pressure") {
    bc.type = BoundaryCondition::Type::kPressure;
    bc.values[0] = read_scalar(j["pressure"]);
  } else {
    bc.type = BoundaryCondition::Type::kContact;
    bc.obstacle = read_obstacle(j["obstacle"]);
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

ValueRule scalar_pair_value(const CaseReadOptions& options) {
  return tuple_value(scalar_value(options.limits.max_expression_length), 2,
                     "an array of 2 numbers or expressions of x and y");
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

std::array<Scalar, 2> read_scalar_pair(const json& j) {
  return {read_scalar(j[0]), read_scalar(j[1])};
}

ValueRule boundary_rule(const CaseReadOptions& options) {
  return map_value(name_value(options.limits.max_name_length, "the boundary group name"),
                   object_value(condition_rule(options)), options.limits.max_geometry_entities,
                   "object mapping boundary group names to conditions", "conditions");
}

std::map<std::string, BoundaryCondition> read_boundary_section(const json& j) {
  std::map<std::string, BoundaryCondition> boundary;
  for (const auto& [name, condition] : j.items()) boundary[name] = read_condition(condition);
  return boundary;
}

}  // namespace fosls
