#include "case/contact3d_section.hpp"

#include "case/case_sections.hpp"
#include "case/expression.hpp"
#include "case/rule_checker.hpp"

namespace fosls {

namespace {

using nlohmann::json;

FieldRule plane_point_field(bool required) {
  const std::string meaning = "a point [x, y, z] of the plane";
  return required ? required_field("point", vector3_value("[x, y, z]"), meaning)
                  : optional_field("point", vector3_value("[x, y, z]"), nullptr, meaning);
}

FieldRule plane_normal_field(bool required) {
  const std::string meaning =
      "the normal [nx, ny, nz] from the plane into the body (any non-zero length; it is "
      "normalised)";
  return required ? required_field("normal", vector3_value("[nx, ny, nz]"), meaning)
                  : optional_field("normal", vector3_value("[nx, ny, nz]"), nullptr, meaning);
}

void check_normal_not_zero(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!j.contains("normal") || !checker.usable(j, pointer, {"normal"})) return;
  if (read_vector3(j["normal"]).norm() == 0)
    checker.error(child_pointer(pointer, "normal"), "the normal must not be zero");
}

FieldRule obstacle_displacement_field() {
  return optional_field("displacement", vector3_value("[dx, dy, dz]"), json::array({0, 0, 0}),
                        "rigid displacement [dx, dy, dz] of the obstacle from where point/center "
                        "put it; [0, 0, 0.01] moves it 0.01 up, into a body above it");
}

ObjectRulePtr obstacle3d_rule(const CaseReadOptions& options) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "a 3D obstacle";
  r->anchor = "obstacle3d";
  r->discriminator = "type";
  r->discriminator_meaning = "plane, sphere or gap";
  r->variants = {
      {"plane",
       "a plane obstacle",
       "a rigid half-space; the gap is the distance to its plane",
       {plane_point_field(true), plane_normal_field(true), obstacle_displacement_field()},
       check_normal_not_zero,
       "the normal is not zero"},
      {"sphere",
       "a sphere obstacle",
       "a rigid ball; the body lies outside it; the gap is the distance to its sphere",
       {required_field("center", vector3_value("[x, y, z]"), "the centre [x, y, z] of the ball"),
        required_field("radius", number_value(Range::positive()), "the radius of the ball"),
        obstacle_displacement_field()},
       {},
       ""},
      {"gap",
       "a gap obstacle",
       "the gap g(x, y, z) itself, measured along the body normal",
       {required_field("g", scalar3_value(options.limits.max_expression_length),
                       "the gap g(x, y, z): a number or an expression of x, y and z")},
       {},
       ""},
  };
  return r;
}

/// Exactly one of the two forms, and the short form whole.
void check_one_obstacle(const json& j, const std::string& pointer, RuleChecker& checker) {
  const bool plane = j.contains("point") || j.contains("normal");
  if (plane && j.contains("obstacle")) {
    checker.error(pointer,
                  "give the obstacle either as point and normal (a plane) or as obstacle, "
                  "not both");
    return;
  }
  if (!plane && !j.contains("obstacle")) {
    checker.error(child_pointer(pointer, "obstacle"),
                  "missing field \"obstacle\": the rigid obstacle (a plane, sphere or gap), or "
                  "the plane's point and normal");
    return;
  }
  for (const char* key : {"point", "normal"})
    if (plane && !j.contains(key))
      checker.error(child_pointer(pointer, key),
                    std::string("missing field \"") + key +
                        "\": a plane given by point and normal needs both");
  check_normal_not_zero(j, pointer, checker);
}

}  // namespace

Point3 read_vector3(const json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

ObjectVariant contact3d_variant(const CaseReadOptions& options) {
  return {"contact",
          "a contact condition",
          "frictionless contact with a rigid obstacle, the gap measured along the body normal",
          {plane_point_field(false), plane_normal_field(false),
           optional_field("obstacle", object_value(obstacle3d_rule(options)), nullptr,
                          "the rigid obstacle: a plane, sphere or gap (instead of point and "
                          "normal)")},
          check_one_obstacle,
          "either point and normal (a plane) or obstacle; the normal is not zero"};
}

Obstacle3d read_obstacle3d(const json& condition) {
  Obstacle3d o;
  const bool short_form = !condition.contains("obstacle");
  const json& j = short_form ? condition : condition["obstacle"];
  const std::string type = short_form ? "plane" : j["type"].get<std::string>();
  o.as_object = !short_form;
  if (j.contains("displacement")) o.displacement = read_vector3(j["displacement"]);
  if (type == "sphere") {
    o.kind = Obstacle3d::Kind::kSphere;
    o.center = read_vector3(j["center"]);
    o.radius = j["radius"].get<double>();
  } else if (type == "gap") {
    o.kind = Obstacle3d::Kind::kGap;
    o.gap = compile_scalar_3d(read_scalar(j["g"]));
  } else {
    o.point = read_vector3(j["point"]);
    o.normal = read_vector3(j["normal"]).normalized();
  }
  return o;
}

}  // namespace fosls
