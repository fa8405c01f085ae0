// A prescribed displacement along a frictionless plane contact that nothing else resists: the
// body slides on the obstacle as a whole instead of being sheared (result_warnings.hpp). The
// same rule in 2D and 3D: the tangential part of what the dirichlet groups prescribe is taken
// with the projector I − n nᵀ onto the contact plane (a line in 2D).

#include <cmath>
#include <map>

#include "case/result/result_warnings.hpp"

namespace fosls {

namespace {

using Vector3 = Eigen::Vector3d;

std::string num(double v) { return sentence_number(v); }

/// The common unit normal of the case's contacts when every one is a frictionless plane and all
/// planes are parallel (the only contacts along which a tangent is defined), with their names.
std::optional<Vector3> plane_contact_normal(const CaseSpec& spec, std::string& names) {
  std::optional<Vector3> normal;
  for (const auto& [name, bc] : spec.boundary) {
    if (bc.type != BoundaryCondition::Type::kContact) continue;
    if (!is_frictionless(bc) || bc.obstacle.kind != Obstacle::Kind::kPlane) return std::nullopt;
    Vector3 n = Vector3::Zero();
    n.head(spec.dimension) = bc.obstacle.normal.head(spec.dimension).normalized();
    if (normal && normal->cross(n).norm() > 1e-9) return std::nullopt;
    normal = n;
    names += (names.empty() ? "'" : ", '") + name + "'";
  }
  return normal;
}

/// "(x, y)" or "(x, y, z)" (the caller adds +0 so that no −0 is written).
std::string components(const Vector3& v, int dim) {
  std::string s = "(" + num(v.x()) + ", " + num(v.y());
  if (dim == 3) s += ", " + num(v.z());
  return s + ")";
}

}  // namespace

std::optional<ResultWarning> tangential_load_warning(const CaseSpec& spec) {
  const int dim = spec.dimension;
  std::string contacts;
  const std::optional<Vector3> normal = plane_contact_normal(spec, contacts);
  if (!normal) return std::nullopt;
  const Eigen::Matrix3d tangential = Eigen::Matrix3d::Identity() - *normal * normal->transpose();
  // Per displacement component that has a tangential part: the values the groups prescribe.
  std::map<int, std::map<double, std::string>> held;  // component → value → a group
  for (const auto& [name, bc] : spec.boundary) {
    if (bc.type != BoundaryCondition::Type::kDirichlet) continue;
    for (int c = 0; c < dim; ++c) {
      if (!bc.prescribed[c] || tangential.col(c).norm() < 1e-12) continue;
      if (!bc.values[c].is_constant()) return std::nullopt;  // varies along the group
      held[c][bc.values[c].value] = name;
    }
  }
  Vector3 prescribed = Vector3::Zero();  // what every holding group prescribes alike
  std::string group;
  for (const auto& [c, values] : held) {
    if (values.size() != 1) return std::nullopt;  // two groups pull against each other
    prescribed[c] = values.begin()->first;
    group = values.begin()->second;
  }
  const Vector3 slide = tangential * prescribed;
  if (held.empty() || slide.norm() < 1e-300) return std::nullopt;
  return ResultWarning{
      "tangential_load_frictionless",
      "a tangential displacement of " + num(slide.norm()) +
          " along the plane of the frictionless contact " + contacts + " (direction " +
          components(slide.normalized() + Vector3::Zero(), dim) + ") is prescribed on group '" +
          group +
          "' and held by nothing else: a frictionless contact transmits no shear, so the body "
          "slides on the obstacle as a whole (a rigid translation by that much) and the "
          "tangential displacement produces no shear stress. If the contact should hold the "
          "body (friction), this case cannot show it; to load the body in shear, hold it "
          "elsewhere with a different tangential displacement",
      false};
}

}  // namespace fosls
