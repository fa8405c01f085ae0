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

/// Kuhn cubes of the half cube [−1, 1]² × [−1, 0], n cubes deep, each split along the diagonal
/// from its vertex nearest the origin outwards. Every tetrahedron then holds a vertex off the five
/// faces that go onto the sphere: with make_box's one diagonal direction, tetrahedra at the
/// mapped cube's corners had all four vertices on the sphere and flattened under refinement.
/// Each tetrahedron's vertices are in path order, so refinement keeps them Kuhn tetrahedra.
std::pair<std::vector<Point3>, std::vector<std::array<int, 4>>> outward_kuhn_half_cube(int n) {
  auto id = [n](int i, int j, int k) { return (k * (2 * n + 1) + j) * (2 * n + 1) + i; };
  std::vector<Point3> points;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= 2 * n; ++j)
      for (int i = 0; i <= 2 * n; ++i)
        points.emplace_back(-1.0 + double(i) / n, -1.0 + double(j) / n, -double(k) / n);
  std::vector<std::array<int, 4>> tets;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < 2 * n; ++j)
      for (int i = 0; i < 2 * n; ++i)  // away from the axis in x and y, downwards in z
        append_kuhn_cube({i < n ? i + 1 : i, j < n ? j + 1 : j, k},
                         {i < n ? -1 : 1, j < n ? -1 : 1, 1}, id, tets);
  return {std::move(points), std::move(tets)};
}

/// The tetrahedra in x ≥ 0, y ≥ 0 (whole cubes there) and their vertices, renumbered in order.
void keep_quarter(std::vector<Point3>& points, std::vector<std::array<int, 4>>& tets) {
  std::vector<int> index(points.size(), -1);
  std::vector<std::array<int, 4>> kept;
  for (const auto& t : tets) {
    bool inside = true;
    for (int v : t) inside &= points[v].x() >= 0.0 && points[v].y() >= 0.0;
    if (inside) kept.push_back(t);
  }
  for (const auto& t : kept)
    for (int v : t) index[v] = 0;
  std::vector<Point3> used;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (index[v] == 0) index[v] = static_cast<int>(used.size()), used.push_back(points[v]);
  for (auto& t : kept)
    for (int& v : t) v = index[v];
  points.swap(used);
  tets.swap(kept);
}

}  // namespace

TetMesh make_half_ball(const HalfBallSpec& spec) {
  if (!(spec.radius > 0) || spec.cells < 1 || spec.cells > 64 || !(spec.grading >= 1.0) ||
      spec.grading > 4.0 || !(spec.contact_fraction > 0) || spec.contact_fraction > 1.0)
    throw std::invalid_argument(
        "make_half_ball: radius > 0, cells 1–64, grading 1–4, "
        "contact_fraction in (0, 1] expected");
  auto [reference, tets] = outward_kuhn_half_cube(spec.cells);
  if (spec.quarter) keep_quarter(reference, tets);
  std::vector<Point3> vertices;
  for (const Point3& xi : reference)
    vertices.push_back(half_ball_point(xi, spec.grading, spec.radius));
  for (const auto& t : tets)
    if (signed_volume(reference, t) * signed_volume(vertices, t) <= 0)
      throw std::invalid_argument("make_half_ball: the grading folds a tetrahedron");
  const int top = 0, contact = 1, free = 2, symmetry_x = 3, symmetry_y = 4;
  const TetMesh cube(reference, tets, {}, {});
  std::vector<BoundaryFace> boundary;
  for (int f = 0; f < cube.num_faces(); ++f) {
    if (!cube.is_boundary_face(f)) continue;
    // The top z = 0 stays flat; the half cube's five other sides go onto the sphere; a quarter's
    // cut planes x = 0 and y = 0 stay where they are.
    const auto& v = cube.face(f);
    int group = top;
    if (spec.quarter && cube.face_normal(f).x() < -0.5) {
      group = symmetry_x;
    } else if (spec.quarter && cube.face_normal(f).y() < -0.5) {
      group = symmetry_y;
    } else if (cube.face_normal(f).z() < 0.5) {
      const Point3 c = (vertices[v[0]] + vertices[v[1]] + vertices[v[2]]) / 3.0;
      group = std::hypot(c.x(), c.y()) <= spec.contact_fraction * spec.radius ? contact : free;
    }
    boundary.push_back({v, group});
  }
  const SphereSurface sphere{Point3::Zero(), spec.radius};
  if (spec.quarter)
    return TetMesh(std::move(vertices), std::move(tets), boundary,
                   {"top", "contact", "free", "symmetry_x", "symmetry_y"},
                   {SphereSurface{}, sphere, sphere, SphereSurface{}, SphereSurface{}});
  return TetMesh(std::move(vertices), std::move(tets), boundary, {"top", "contact", "free"},
                 {SphereSurface{}, sphere, sphere});
}

}  // namespace fosls
