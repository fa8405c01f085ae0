#include "mesh/tet_quality.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace fosls {

double smallest_dihedral_angle(const TetMesh& mesh, int tet) {
  const auto& t = mesh.tet(tet);
  // Face k is opposite vertex k; its area vector points away from that vertex. The dihedral angle
  // at the edge shared by faces a and b is π minus the angle between their outward normals.
  std::array<Point3, 4> outward;
  for (int k = 0; k < 4; ++k) {
    const Point3& p = mesh.vertex(t[(k + 1) % 4]);
    const Point3 n = (mesh.vertex(t[(k + 2) % 4]) - p).cross(mesh.vertex(t[(k + 3) % 4]) - p);
    outward[k] = n.dot(p - mesh.vertex(t[k])) >= 0 ? n.normalized() : Point3(-n.normalized());
  }
  double smallest = M_PI;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      smallest =
          std::min(smallest, M_PI - std::acos(std::clamp(outward[a].dot(outward[b]), -1.0, 1.0)));
  return smallest * 180.0 / M_PI;
}

double smallest_dihedral_angle(const TetMesh& mesh) {
  double smallest = 180.0;
  for (int t = 0; t < mesh.num_tets(); ++t)
    smallest = std::min(smallest, smallest_dihedral_angle(mesh, t));
  return smallest;
}

}  // namespace fosls
