// The `mesh.geometry` section: points, lines and arcs forming one closed loop, and the named
// boundary groups of its curves.

#include "case/format/case_sections.hpp"
#include "case/format/rule_checker.hpp"
#include "case/run/mesh_factory.hpp"
#include "mesh/geometry_checks.hpp"

namespace fosls {

namespace {

using nlohmann::json;

ObjectRulePtr curve_rule() {
  auto r = std::make_shared<ObjectRule>();
  r->title = "a curve";
  r->anchor = "curve";
  r->discriminator = "type";
  r->discriminator_meaning = "\"line\" or \"arc\"";
  const ValueRule index = integer_value(Range::non_negative());
  const ValueRule ends = tuple_value(index, 2, "an array of 2 point indices");
  r->variants = {
      {"line",
       "a line",
       "the segment from point i to point j",
       {required_field("points", ends, "the indices [i, j] of its end points")},
       {},
       ""},
      {"arc",
       "an arc",
       "the circular arc from point i to point j around point k, the shorter way",
       {required_field("points", ends, "the indices [i, j] of its end points"),
        required_field("center", index, "the index k of the arc's centre point")},
       {},
       ""},
  };
  return r;
}

/// The geometric rules (indices that name points and curves, curve shapes, group membership,
/// one closed loop, no crossings) are the mesh layer's own validation, the same that guards
/// the mesher: one wording and one pointer per problem.
void check_geometry(const json& j, const std::string& pointer, RuleChecker& checker) {
  for (const char* key : {"points", "curves", "groups"})
    if (!j.contains(key) || !checker.passed(child_pointer(pointer, key))) return;
  MeshSpec mesh;
  mesh.kind = MeshSpec::Kind::kGeometry;
  mesh.geometry = read_geometry_section(j);
  for (const MeshProblem& p : validate_geometry(mesh.geometry))
    checker.error(mesh_problem_pointer(p, mesh), p.detail);
}

}  // namespace

ObjectRulePtr geometry_rule(const CaseReadOptions& options) {
  const CaseLimits& limits = options.limits;
  const std::size_t max = limits.max_geometry_entities;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the geometry";
  r->anchor = "geometry";
  ValueRule curve_indices =
      array_value(integer_value(Range::non_negative()), max, "array of curve indices");
  r->fields = {
      required_field("points", array_value(point_value(), max, "array of points [x, y]"),
                     "the points [x, y] of the geometry"),
      required_field("curves", array_value(object_value(curve_rule()), max, "array of curves"),
                     "lines and arcs forming one closed loop"),
      required_field(
          "groups",
          map_value(name_value(limits.max_name_length, "the group name"), curve_indices, max,
                    "object mapping each boundary group name to a list of curve indices", "groups"),
          "named lists of curve indices"),
  };
  r->hook = check_geometry;
  r->notes =
      "indices name existing points and curves; a curve has positive length; an arc's end "
      "points are equidistant from its centre (relative tolerance 1e-9) and it is not a half "
      "circle; every curve is in exactly one group; the curves form one closed loop and do not "
      "cross or touch other than at shared end points";
  return r;
}

GeometrySpec read_geometry_section(const json& j) {
  GeometrySpec g;
  for (const auto& p : j.at("points"))
    g.points.emplace_back(p[0].get<double>(), p[1].get<double>());
  if (const auto it = j.find("curves"); it != j.end())
    for (const auto& c : *it) {
      GeometrySpec::Curve curve;
      curve.is_arc = c.at("type") == "arc";
      curve.points = {c.at("points")[0].get<int>(), c.at("points")[1].get<int>()};
      if (curve.is_arc) curve.center = c.at("center").get<int>();
      g.curves.push_back(curve);
    }
  if (const auto it = j.find("groups"); it != j.end())
    for (const auto& [name, list] : it->items())
      g.groups.push_back({name, list.get<std::vector<int>>()});
  return g;
}

CoarseMeshEstimate estimated_coarse_mesh(const GeometrySpec& g, double size) {
  SizeField field;
  field.size = size;
  return estimate_coarse_mesh(g, field);
}

}  // namespace fosls
