#include "case/result/symmetry_planes.hpp"

#include <cmath>
#include <optional>

namespace fosls {

namespace {

/// The axis of a roller that holds the one component it prescribes at 0; none otherwise.
std::optional<int> zero_roller_axis(const BoundaryCondition& bc) {
  if (bc.type != BoundaryCondition::Type::kDirichlet) return std::nullopt;
  std::optional<int> axis;
  for (int k = 0; k < 3; ++k) {
    if (!bc.prescribed[k]) continue;
    if (axis || !bc.values[k].is_constant() || bc.values[k].value != 0.0) return std::nullopt;
    axis = k;
  }
  return axis;
}

/// The plane of group g's faces when they lie in one plane normal to `axis`.
std::optional<MirrorPlane> group_plane(const TetMesh& mesh, int g, int axis) {
  constexpr double kNormalTolerance = 1e-9;
  const double tolerance = 1e-9 * mesh.diameter();
  std::optional<MirrorPlane> plane;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (mesh.face_group(f) != g) continue;
    if (std::abs(std::abs(mesh.face_normal(f)[axis]) - 1.0) > kNormalTolerance) return std::nullopt;
    for (int v : mesh.face(f)) {
      const Point3& x = mesh.vertex(v);
      if (!plane) plane = MirrorPlane{x, Point3::Unit(axis)};
      if (std::abs(x[axis] - plane->point[axis]) > tolerance) return std::nullopt;
    }
  }
  return plane;
}

}  // namespace

std::vector<MirrorPlane> symmetry_planes(const CaseSpec& spec, const TetMesh& mesh) {
  std::vector<MirrorPlane> planes;
  const std::vector<std::string>& names = mesh.group_names();
  for (int g = 0; g < static_cast<int>(names.size()); ++g) {
    const auto bc = spec.boundary.find(names[g]);
    if (bc == spec.boundary.end()) continue;
    if (const std::optional<int> axis = zero_roller_axis(bc->second))
      if (const std::optional<MirrorPlane> plane = group_plane(mesh, g, *axis))
        planes.push_back(*plane);
  }
  return planes;
}

std::vector<MirrorPlane> planes_against(const std::vector<MirrorPlane>& planes, const TetMesh& mesh,
                                        const std::vector<int>& zone_faces) {
  const double tolerance = 1e-9 * mesh.diameter();
  std::vector<MirrorPlane> against;
  for (const MirrorPlane& plane : planes) {
    bool touches = false;
    for (int f : zone_faces)
      for (int v : mesh.face(f))
        touches |= std::abs((mesh.vertex(v) - plane.point).dot(plane.normal)) <= tolerance;
    if (touches) against.push_back(plane);
  }
  return against;
}

}  // namespace fosls
