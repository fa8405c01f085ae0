// A prescribed displacement along a frictionless plane contact that nothing else resists: the
// body slides on the obstacle as a whole instead of being sheared (result_warnings.hpp).

#include <cmath>
#include <map>

#include "case/result_warnings.hpp"

namespace fosls {

namespace {

std::string num(double v) { return sentence_number(v); }

/// The common normal of the case's contacts when every one is a frictionless plane and all
/// planes are parallel (the only contacts along which a tangent is defined), with their names.
std::optional<Point> plane_contact_normal(const CaseSpec& spec, std::string& names) {
  std::optional<Point> normal;
  for (const auto& [name, bc] : spec.boundary) {
    if (bc.type != BoundaryCondition::Type::kContact) continue;
    if (!is_frictionless(bc) || bc.obstacle.kind != Obstacle::Kind::kPlane) return std::nullopt;
    const Point n = bc.obstacle.normal.head<2>();
    if (normal && std::abs(normal->x() * n.y() - normal->y() * n.x()) > 1e-9) return std::nullopt;
    normal = n;
    names += (names.empty() ? "'" : ", '") + name + "'";
  }
  return normal;
}

}  // namespace

std::optional<ResultWarning> tangential_load_warning(const CaseSpec& spec) {
  std::string contacts;
  const std::optional<Point> normal = plane_contact_normal(spec, contacts);
  if (!normal) return std::nullopt;
  const Point t(-normal->y(), normal->x());
  // Per displacement component along which t moves: the values the dirichlet groups prescribe.
  std::map<int, std::map<double, std::string>> held;  // component → value → a group
  for (const auto& [name, bc] : spec.boundary) {
    if (bc.type != BoundaryCondition::Type::kDirichlet) continue;
    for (int c = 0; c < 2; ++c) {
      if (!bc.prescribed[c] || std::abs(t[c]) < 1e-12) continue;
      if (!bc.values[c].is_constant()) return std::nullopt;  // varies along the group
      held[c][bc.values[c].value] = name;
    }
  }
  double slide = 0.0;  // the tangential displacement every holding group prescribes alike
  std::string group;
  for (const auto& [c, values] : held) {
    if (values.size() != 1) return std::nullopt;  // two groups pull against each other
    slide += values.begin()->first * t[c];
    group = values.begin()->second;
  }
  if (held.empty() || slide == 0.0) return std::nullopt;
  const Point along = slide > 0 ? t : Point(-t + Point::Zero());  // say it as a positive amount
  return ResultWarning{
      "tangential_load_frictionless",
      "a tangential displacement of " + num(std::abs(slide)) +
          " along the plane of the frictionless "
          "contact " +
          contacts + " (direction (" + num(along.x()) + ", " + num(along.y()) +
          ")) is prescribed on group '" + group +
          "' and held by nothing else: a frictionless contact transmits no shear, so the body "
          "slides on the obstacle as a whole (a rigid translation by that much) and the "
          "tangential displacement produces no shear stress. If the contact should hold the "
          "body (friction), this case cannot show it; to load the body in shear, hold it "
          "elsewhere with a different tangential displacement",
      false};
}

}  // namespace fosls
