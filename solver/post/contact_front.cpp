#include "post/contact_front.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "fem/contact_frame.hpp"

namespace fosls {

namespace {

/// A vertex with no loaded face near it: the front passes through its loaded neighbours.
constexpr double kOutside = -std::numeric_limits<double>::infinity();

/// The contact faces at each vertex that has one.
using VertexFaces = std::map<int, std::vector<int>>;

VertexFaces faces_at_vertices(const TetMesh& mesh, const std::vector<int>& faces) {
  VertexFaces at;
  for (int f : faces)
    for (int v : mesh.face(f)) at[v].push_back(f);
  return at;
}

/// The points where the fit at x sees a loaded face with centroid c: c, and its mirror images
/// across the planes through x.
std::vector<Point3> seen_at(const Point3& x, const Point3& c, const std::vector<MirrorPlane>& m,
                            double tolerance) {
  std::vector<Point3> points = {c};
  for (const MirrorPlane& plane : m)
    if (std::abs((x - plane.point).dot(plane.normal)) <= tolerance)
      for (std::size_t k = 0, n = points.size(); k < n; ++k)
        points.push_back(points[k] -
                         2.0 * (points[k] - plane.point).dot(plane.normal) * plane.normal);
  return points;
}

/// p² at vertex v from the plane fitted by least squares through the p² of the loaded faces
/// that share a vertex with v's faces (and their mirror images), in v's tangent coordinates. A
/// vertex whose own faces are all loaded lies inside the zone however its fit turns out;
/// kOutside without three loaded faces to fit. A vertex within `tolerance` of a mirror is on it.
double squared_pressure_at(const TetMesh& mesh, const VertexFaces& at, int v,
                           const std::vector<double>& pressure,
                           const std::vector<MirrorPlane>& mirrors, double tolerance) {
  const std::vector<int>& own = at.at(v);
  std::set<int> near;
  Point3 normal = Point3::Zero();
  for (int f : own) {
    normal += mesh.face_area(f) * mesh.face_normal(f);
    for (int w : mesh.face(f))
      for (int g : at.at(w))
        if (pressure[g] > 0) near.insert(g);
  }
  if (near.size() < 3) return kOutside;
  const Mat<3> frame = normal_frame<3>(normal.normalized());
  const Point3 t1 = frame.col(1), t2 = frame.col(2);
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (int f : near)
    for (const Point3& c : seen_at(mesh.vertex(v), mesh.face_centroid(f), mirrors, tolerance)) {
      const Point3 d = c - mesh.vertex(v);
      const Eigen::Vector3d phi(1.0, d.dot(t1), d.dot(t2));
      normal_matrix += phi * phi.transpose();
      rhs += phi * (pressure[f] * pressure[f]);
    }
  const Eigen::LDLT<Eigen::Matrix3d> fit(normal_matrix);
  const double value = fit.info() == Eigen::Success ? fit.solve(rhs)[0] : kOutside;
  const bool inside = std::all_of(own.begin(), own.end(), [&](int f) { return pressure[f] > 0; });
  if (inside) return std::max(value, std::numeric_limits<double>::min());
  return std::isfinite(value) ? value : kOutside;
}

double triangle_area(const Point3& a, const Point3& b, const Point3& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

/// The area of the part of triangle x where the linear interpolant of q is positive (a q of
/// kOutside puts the crossing at the other end of the edge).
double positive_part_area(const std::array<Point3, 3>& x, const std::array<double, 3>& q) {
  std::vector<Point3> polygon;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (q[i] > 0) polygon.push_back(x[i]);
    if ((q[i] > 0) == (q[j] > 0)) continue;
    const double t = std::isinf(q[j]) ? 0.0 : std::isinf(q[i]) ? 1.0 : q[i] / (q[i] - q[j]);
    polygon.push_back(x[i] + t * (x[j] - x[i]));
  }
  double area = 0.0;
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
    area += triangle_area(polygon[0], polygon[k], polygon[k + 1]);
  return area;
}

}  // namespace

double area_within_front(const TetMesh& mesh, const std::vector<int>& faces,
                         const std::vector<double>& pressure,
                         const std::vector<MirrorPlane>& mirrors) {
  const VertexFaces at = faces_at_vertices(mesh, faces);
  // Once, not per vertex: the diameter reads every vertex of the mesh.
  const double tolerance = 1e-9 * mesh.diameter();
  std::map<int, double> q;
  for (int f : faces)
    if (pressure[f] > 0)
      for (int v : mesh.face(f))
        if (!q.count(v)) q[v] = squared_pressure_at(mesh, at, v, pressure, mirrors, tolerance);
  double area = 0.0;
  for (int f : faces) {
    if (!(pressure[f] > 0)) continue;
    const std::array<int, 3>& v = mesh.face(f);
    area += std::min(mesh.face_area(f),
                     positive_part_area({mesh.vertex(v[0]), mesh.vertex(v[1]), mesh.vertex(v[2])},
                                        {q[v[0]], q[v[1]], q[v[2]]}));
  }
  return area;
}

}  // namespace fosls
