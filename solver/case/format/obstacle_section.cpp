// The contact condition and its rigid obstacle: a plane, a circle (2D) or sphere (3D), or the gap
// as a function, given as `obstacle` or, for a plane, by the condition's own `point` and `normal`;
// friction and the constraint direction.

#include "case/format/case_sections.hpp"
#include "case/format/rule_checker.hpp"

namespace fosls {

namespace {

using nlohmann::json;

ValueRule point_in(int dim) {
  return vector_value(dim, number_value(), "an array of 2 numbers [x, y]",
                      "an array of 3 numbers [x, y, z]");
}

std::string names(int dim, const std::string& two, const std::string& three) {
  return in_dimension(dim, "[" + two + "]", "[" + three + "]");
}

FieldRule plane_point_field(int dim, bool required) {
  const std::string meaning = "a point " + names(dim, "x, y", "x, y, z") + " on the plane";
  return required ? required_field("point", point_in(dim), meaning)
                  : optional_field("point", point_in(dim), nullptr, meaning);
}

FieldRule plane_normal_field(int dim, bool required) {
  const std::string meaning = "the normal " + names(dim, "nx, ny", "nx, ny, nz") +
                              " from the obstacle into the body (any non-zero length; it is "
                              "normalised)";
  return required ? required_field("normal", point_in(dim), meaning)
                  : optional_field("normal", point_in(dim), nullptr, meaning);
}

/// A plane's normal gives its orientation, so it cannot be zero.
void check_plane(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!checker.usable(j, pointer, {"normal"}) || !j.contains("normal")) return;
  if (read_vector(j["normal"]).norm() == 0.0)
    checker.error(child_pointer(pointer, "normal"), "the normal is zero; give a non-zero vector");
}

/// A rigid-body motion of a plane or round obstacle, so that an indentation is a case field
/// (and a sweep parameter) rather than a change of the body's Dirichlet data.
FieldRule obstacle_displacement_field(int dim) {
  const json none = dim == 3 ? json::array({0, 0, 0}) : json::array({0, 0});
  return optional_field("displacement", point_in(dim), dim == 0 ? json() : none,
                        "rigid displacement " + names(dim, "dx, dy", "dx, dy, dz") +
                            " of the obstacle from where point/center put it; " +
                            in_dimension(dim, "[0, 0.01]", "[0, 0, 0.01]") +
                            " moves it 0.01 up, into a body above it" +
                            (dim == 0 ? "; absent: none" : ""));
}

ObjectVariant circle_variant(int dim) {
  if (dim == 3)
    return refused_variant("circle",
                           "circle is the round obstacle of a 2D case; in 3D it is \"sphere\" "
                           "(center [x, y, z] and radius)");
  return {"circle",
          "a circle obstacle",
          std::string(dim == 0 ? "(2D) " : "") +
              "a rigid disk; the body lies outside it; the gap is the distance to the circle",
          {required_field("center", point_in(2), "the centre [x, y] of the circle"),
           required_field("radius", number_value(Range::positive()), "the radius of the circle"),
           obstacle_displacement_field(2)},
          {},
          ""};
}

ObjectVariant sphere_variant(int dim) {
  if (dim == 2)
    return refused_variant("sphere",
                           "sphere is the round obstacle of a 3D case (a 3D case needs "
                           "\"dimension\": 3); in 2D it is \"circle\" (center [x, y] and radius)");
  return {"sphere",
          "a sphere obstacle",
          std::string(dim == 0 ? "(3D) " : "") +
              "a rigid ball; the body lies outside it; the gap is the distance to its sphere",
          {required_field("center", point_in(3), "the centre [x, y, z] of the ball"),
           required_field("radius", number_value(Range::positive()), "the radius of the ball"),
           obstacle_displacement_field(3)},
          {},
          ""};
}

ObjectRulePtr obstacle_rule(const CaseReadOptions& options, int dim) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "an obstacle";
  r->anchor = "obstacle";
  r->discriminator = "type";
  r->discriminator_meaning = "plane, " + in_dimension(dim, "circle", "sphere") + " or gap";
  const std::string g = in_dimension(dim, "g(x, y)", "g(x, y, z)");
  r->variants = {
      {"plane",
       "a plane obstacle",
       "a rigid half " + in_dimension(dim, "plane", "space") + "; the gap is the distance to it",
       {plane_point_field(dim, true), plane_normal_field(dim, true),
        obstacle_displacement_field(dim)},
       check_plane,
       "the normal is not zero"},
      circle_variant(dim),
      sphere_variant(dim),
      {"gap",
       "a gap obstacle",
       "the gap " + g + " itself, measured along the body normal",
       {required_field("g", scalar_value_in(dim, options.limits.max_expression_length),
                       "the gap " + g + ": a number or an expression of " +
                           in_dimension(dim, "x and y", "x, y and z"))},
       {},
       ""},
  };
  return r;
}

/// Tresca's bound: a number must be >= 0 now; an expression is checked where it is evaluated.
ValueRule slip_bound_value(int dim, std::size_t max_expression_length) {
  ValueRule v = scalar_value_in(dim, max_expression_length);
  v.hook = [](const json& value, const std::string& pointer, RuleChecker& checker) {
    if (!value.is_number() || value.get<double>() >= 0.0) return true;
    checker.error(pointer, "the slip bound is " + value.dump() + "; it must be >= 0");
    return false;
  };
  v.notes = "a number must be >= 0";
  return v;
}

ObjectRulePtr friction_rule(const CaseReadOptions& options, int dim) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "the friction law";
  r->anchor = "friction";
  r->fields = {
      optional_field("coefficient", number_value(Range::closed(0, 10)), nullptr,
                     "Coulomb's coefficient 𝔣: |σ_nt| ≤ 𝔣 |σ_nn|; 0 is frictionless"),
      optional_field("bound", slip_bound_value(dim, options.limits.max_expression_length), nullptr,
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

/// The obstacle's normal is needed to constrain the displacement along it.
void check_direction(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!j.contains("direction") || !j.contains("obstacle") ||
      !checker.usable(j, pointer, {"obstacle", "direction"}))
    return;
  if (j["direction"] == "obstacle_normal" && j["obstacle"]["type"] == "gap")
    checker.error(
        child_pointer(pointer, "direction"),
        "direction obstacle_normal needs a plane, circle (2D) or sphere (3D) obstacle; a gap "
        "obstacle has no normal of its own (use body_normal)");
}

/// The direction, and a plane given by the condition's own point and normal.
void check_contact(const json& j, const std::string& pointer, RuleChecker& checker) {
  check_direction(j, pointer, checker);
  check_plane(j, pointer, checker);
}

}  // namespace

ObjectVariant contact_variant(const CaseReadOptions& options, int dim) {
  const std::string round = in_dimension(dim, "circle", "sphere");
  return {
      "contact",
      "a contact condition",
      "contact with a rigid obstacle, frictionless unless `friction` is given",
      {optional_field("obstacle", object_value(obstacle_rule(options, dim)), nullptr,
                      "a plane, " + round + " or gap"),
       plane_point_field(dim, false), plane_normal_field(dim, false),
       optional_field("friction", object_value(friction_rule(options, dim)), nullptr,
                      "Coulomb or Tresca friction (docs/method.md §8); absent: frictionless"),
       optional_field("direction", choice_value({"body_normal", "obstacle_normal"}), "body_normal",
                      "the constrained displacement component: u·n with the body's normal, "
                      "or u·ν with the obstacle's normal")},
      check_contact,
      "obstacle_normal needs a plane or " + round +
          " obstacle; the normal of point and normal is not zero",
      {{{{"obstacle"}, {"point", "normal"}},
        "missing field \"obstacle\": a plane, " + round +
            " or gap (or a plane by the condition's own point and normal)",
        "give the obstacle either as obstacle or as point and normal (a plane), not {given}",
        "obstacle"}}};
}

Point3 read_vector(const json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j.size() > 2 ? j[2].get<double>() : 0.0};
}

Obstacle read_obstacle(const json& condition) {
  Obstacle o;
  o.short_form = !condition.contains("obstacle");
  const json& j = o.short_form ? condition : condition["obstacle"];
  const std::string type = o.short_form ? "plane" : j["type"].get<std::string>();
  const Point3 moved = j.contains("displacement") ? read_vector(j["displacement"]) : Point3::Zero();
  o.displacement = moved;
  if (type == "plane") {
    o.kind = Obstacle::Kind::kPlane;
    o.point = read_vector(j["point"]) + moved;
    o.normal = read_vector(j["normal"]).normalized();
  } else if (type == "circle" || type == "sphere") {
    o.kind = Obstacle::Kind::kBall;
    o.center = read_vector(j["center"]) + moved;
    o.radius = j["radius"].get<double>();
  } else {
    o.kind = Obstacle::Kind::kGap;
    o.gap = read_scalar(j["g"]);
  }
  return o;
}

}  // namespace fosls
