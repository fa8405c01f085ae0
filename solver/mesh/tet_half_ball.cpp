#include "mesh/tet_half_ball.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "mesh/tet_refinement.hpp"

namespace fosls {

namespace {

double signed_volume(const std::vector<Point3>& x, const std::array<int, 4>& t) {
  return (x[t[1]] - x[t[0]]).dot((x[t[2]] - x[t[0]]).cross(x[t[3]] - x[t[0]])) / 6.0;
}

/// The half cube's point ξ on the half ball of radius `radius`, graded towards the pole.
Point3 half_ball_point(Point3 xi, double grading, double radius) {
  // Towards the pole (0, 0, −1) within distance 1, which keeps the bottom face in its plane and
  // leaves the other five faces alone: sizes ∝ d^(grading − 1) at distance d from the pole.
  const Point3 pole(0, 0, -1);
  if (const double d = (xi - pole).norm(); d < 1.0)
    xi = pole + (xi - pole) * std::pow(d, grading - 1.0);
  const double euclid = xi.norm();
  if (euclid == 0.0) return xi;
  return radius * xi * (xi.cwiseAbs().maxCoeff() / euclid);
}

}  // namespace

TetMesh make_half_ball(const HalfBallSpec& spec) {
  if (!(spec.radius > 0) || spec.cells < 1 || spec.cells > 64 || !(spec.grading >= 1.0) ||
      spec.grading > 4.0 || !(spec.contact_fraction > 0) || spec.contact_fraction > 1.0)
    throw std::invalid_argument(
        "make_half_ball: radius > 0, cells 1–64, grading 1–4, "
        "contact_fraction in (0, 1] expected");
  const TetMesh cube = make_box({2 * spec.cells, 2 * spec.cells, spec.cells}, Point3(2, 2, 1));
  std::vector<Point3> reference, vertices;
  std::vector<std::array<int, 4>> tets;
  for (int v = 0; v < cube.num_vertices(); ++v) {
    reference.push_back(cube.vertex(v) - Point3(1, 1, 1));
    vertices.push_back(half_ball_point(reference.back(), spec.grading, spec.radius));
  }
  for (int t = 0; t < cube.num_tets(); ++t) {
    tets.push_back(cube.tet(t));
    if (signed_volume(reference, tets.back()) * signed_volume(vertices, tets.back()) <= 0)
      throw std::invalid_argument("make_half_ball: the grading folds a tetrahedron");
  }
  const int top = 0, contact = 1, free = 2;
  std::vector<BoundaryFace> boundary;
  for (int f = 0; f < cube.num_faces(); ++f) {
    if (!cube.is_boundary_face(f)) continue;
    // make_box's group 5 is its top, z = 0 here; its five other sides go onto the sphere.
    int group = top;
    if (cube.face_group(f) != 5) {
      const auto& v = cube.face(f);
      const Point3 c = (vertices[v[0]] + vertices[v[1]] + vertices[v[2]]) / 3.0;
      group = std::hypot(c.x(), c.y()) <= spec.contact_fraction * spec.radius ? contact : free;
    }
    boundary.push_back({cube.face(f), group});
  }
  const SphereSurface sphere{Point3::Zero(), spec.radius};
  return TetMesh(std::move(vertices), std::move(tets), boundary, {"top", "contact", "free"},
                 {SphereSurface{}, sphere, sphere});
}

}  // namespace fosls
