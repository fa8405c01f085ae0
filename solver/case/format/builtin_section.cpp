// The shipped geometries of `mesh.builtin`: square and hertz in 2D, box and half_ball in 3D. A
// builtin of the other dimension is refused with the sentence that says so.

#include <cmath>
#include <numbers>

#include "case/format/case_sections.hpp"
#include "case/format/rule_checker.hpp"
#include "mesh/builtin_meshes.hpp"

namespace fosls {

namespace {

using nlohmann::json;

ObjectVariant square_variant() {
  const SquareParams square;
  return {"square",
          "the square",
          "",
          {optional_field("x0", number_value(), square.x0, "left edge"),
           optional_field("y0", number_value(), square.y0, "bottom edge"),
           optional_field("width", number_value(Range::positive()), square.width, "width"),
           optional_field("height", number_value(Range::positive()), square.height, "height")},
          {},
          ""};
}

ObjectVariant hertz_variant() {
  const HertzParams hertz;
  return {
      "hertz",
      "the hertz geometry",
      "",
      {optional_field("radius", number_value(Range::positive()), hertz.radius, "radius R"),
       optional_field("contact_fraction", number_value(Range::open(0, 1)), hertz.contact_fraction,
                      "arc points with |x| ≤ contact_fraction · R form the group contact"),
       optional_field("grading", number_value(Range::closed(1, 100)), hertz.grading,
                      "coarse edges grow from size near the origin to grading · size")},
      {},
      ""};
}

ValueRule cells_value(int max) { return integer_value(Range::closed(1, max)); }

/// Every length of a box is positive.
void check_box_lengths(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!j.contains("lengths") || !checker.usable(j, pointer, {"lengths"})) return;
  for (const auto& l : j["lengths"])
    if (!(l.get<double>() > 0)) {
      checker.error(child_pointer(pointer, "lengths"), "every length must be > 0");
      return;
    }
}

ObjectVariant box_variant() {
  return {"box",
          "the box",
          "",
          {optional_field("lengths",
                          tuple_value(number_value(), 3, "an array of 3 numbers [lx, ly, lz]"),
                          json::array({1, 1, 1}), "the edge lengths [lx, ly, lz] (each > 0)"),
           optional_field("cells", tuple_value(cells_value(64), 3, "an array of 3 integers"),
                          json::array({2, 2, 2}), "cubes along x, y and z (each 1 to 64)")},
          check_box_lengths,
          "every length is > 0"};
}

ObjectVariant half_ball_variant() {
  const HalfBallSpec ball;
  return {
      "half_ball",
      "the half ball",
      "",
      {optional_field("radius", number_value(Range::positive()), ball.radius, "radius R"),
       optional_field("cells", cells_value(16), ball.cells,
                      "Kuhn cubes along the depth of the coarse mesh; 2 × cells across"),
       optional_field("grading", number_value(Range::closed(1, 4)), ball.grading,
                      "element sizes grow as (distance to the pole)^(grading − 1)"),
       optional_field("contact_fraction", number_value(Range::open(0, 1)), ball.contact_fraction,
                      "sphere faces within contact_fraction · R of the axis form the group "
                      "contact"),
       optional_field("quarter", boolean_value(), ball.quarter,
                      "only the quarter x ≥ 0, y ≥ 0, with the extra groups symmetry_x (x = 0) "
                      "and symmetry_y (y = 0) for rollers: a quarter of the unknowns")},
      {},
      ""};
}

/// What each builtin is, and in which dimension.
struct Builtin {
  ObjectVariant (*variant)();
  int dimension;
  const char* meaning;
};

const std::vector<Builtin>& builtins() {
  static const std::vector<Builtin> table = {
      {square_variant, 2,
       "the rectangle [x0, x0 + width] × [y0, y0 + height]; boundary groups bottom, right, top, "
       "left"},
      {hertz_variant, 2,
       "the lower half of the disk of radius R centred at (0, R), touching y = 0 at the origin; "
       "boundary groups top, contact, free"},
      {box_variant, 3,
       "the box [0, lx] × [0, ly] × [0, lz] in cubes of six tetrahedra; boundary groups left, "
       "right (x = 0, lx), front, back (y), bottom, top (z)"},
      {half_ball_variant, 3,
       "the half ball {|x| ≤ R, z ≤ 0} centred at the origin, flat face up, graded towards its "
       "pole (0, 0, −R); boundary groups top (z = 0), contact (the sphere within "
       "contact_fraction · R of the axis) and free (the rest of the sphere)"},
  };
  return table;
}

/// Why a builtin of the other dimension is refused.
std::string other_dimension(const std::string& name, int dim) {
  return dim == 2 ? "'" + name +
                        "' is a 3D builtin (box or half_ball): a 3D case needs "
                        "\"dimension\": 3; the 2D builtins are square and hertz"
                  : "'" + name +
                        "' is a 2D builtin (square or hertz); the 3D builtins are box "
                        "and half_ball";
}

std::string names_text(int dim) { return in_dimension(dim, "square or hertz", "box or half_ball"); }

}  // namespace

ObjectRulePtr builtin_rule(int dim) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "the builtin geometry";
  r->anchor = "builtin";
  r->discriminator = "name";
  r->discriminator_meaning = "the builtin geometry, " + names_text(dim);
  for (const Builtin& b : builtins()) {
    ObjectVariant v = b.variant();
    v.meaning = (dim == 0 ? std::string(b.dimension == 2 ? "(2D) " : "(3D) ") : "") + b.meaning;
    if (dim != 0 && dim != b.dimension) v = refused_variant(v.value, other_dimension(v.value, dim));
    r->variants.push_back(std::move(v));
  }
  return r;
}

ValueRule builtin_value(int dim) {
  ValueRule names = choice_value({});
  for (const Builtin& b : builtins()) {
    const std::string name = b.variant().value;
    if (dim == 0 || dim == b.dimension)
      names.choices.push_back(name);
    else
      names.refused_choices.emplace_back(name, other_dimension(name, dim));
  }
  const std::string quoted =
      in_dimension(dim, "\"square\" or \"hertz\"", "\"box\" or \"half_ball\"");
  return one_of_value(
      {names, object_value(builtin_rule(dim))},
      "the name of a builtin geometry (" + quoted + ") or an object {\"name\": ..., parameters}");
}

std::string builtin_meaning(int dim) {
  return dim == 3 ? "a shipped 3D geometry, box or half_ball"
                  : "a shipped geometry, " + names_text(dim);
}

namespace {

/// The name of a builtin and the object with its parameters (empty for the name alone).
std::pair<std::string, json> builtin_parts(const json& j) {
  if (j.is_string()) return {j.get<std::string>(), json::object()};
  return {j.at("name").get<std::string>(), j};
}

}  // namespace

void read_builtin(const json& j, MeshSpec& m) {
  const auto [name, given] = builtin_parts(j);
  m.kind = MeshSpec::Kind::kBuiltin;
  m.builtin = name;
  if (name == "box") {
    if (given.contains("lengths"))
      m.box_lengths = Point3(given["lengths"][0], given["lengths"][1], given["lengths"][2]);
    if (given.contains("cells"))
      for (int i = 0; i < 3; ++i) m.box_cells[i] = given["cells"][i].get<int>();
    return;
  }
  if (name == "half_ball") {
    HalfBallSpec& b = m.half_ball;
    b.radius = given.value("radius", b.radius);
    b.cells = given.value("cells", b.cells);
    b.grading = given.value("grading", b.grading);
    b.contact_fraction = given.value("contact_fraction", b.contact_fraction);
    b.quarter = given.value("quarter", b.quarter);
    return;
  }
  // Every parameter of a 2D builtin, defaults included, so that the mesh builder needs none.
  const ObjectRulePtr rule = builtin_rule(2);  // held: the loop reads into it
  for (const auto& f : rule->variant(name)->fields)
    m.params[f.key] = given.value(f.key, f.default_value).get<double>();
}

double builtin_triangles(const json& j, double size) {
  MeshSpec m;
  read_builtin(j, m);
  if (m.builtin == "square") {
    const double nx = std::max(1.0, std::ceil(m.params["width"] / size));
    const double ny = std::max(1.0, std::ceil(m.params["height"] / size));
    return 2.0 * nx * ny;
  }
  // Ungraded (an upper bound): half disk area over the area of a triangle of edge `size`.
  const double r = m.params["radius"];
  return 0.5 * std::numbers::pi * r * r / (0.433 * size * size);
}

}  // namespace fosls
