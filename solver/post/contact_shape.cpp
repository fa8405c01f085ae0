#include "post/contact_shape.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace fosls {

namespace {

/// The largest distance of the points from the line through their centroid along their
/// principal direction.
double line_deviation(const std::vector<Point>& p, const Point& centroid) {
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const Point& q : p) cov += (q - centroid) * (q - centroid).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  const Point normal = eig.eigenvectors().col(0);  // the smaller eigenvalue's
  double worst = 0.0;
  for (const Point& q : p) worst = std::max(worst, std::abs((q - centroid).dot(normal)));
  return worst;
}

/// The circle x² + y² + D x + E y + F = 0 through the points in the least-squares sense
/// (Kåsa's fit), in coordinates relative to the centroid.
bool fit_circle(const std::vector<Point>& p, const Point& centroid, Point& center, double& r) {
  Eigen::MatrixXd a(p.size(), 3);
  Eigen::VectorXd b(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point q = p[i] - centroid;
    a.row(i) << q.x(), q.y(), 1.0;
    b[i] = -q.squaredNorm();
  }
  const Eigen::Vector3d c = a.colPivHouseholderQr().solve(b);
  const double r2 = 0.25 * (c[0] * c[0] + c[1] * c[1]) - c[2];
  if (!(r2 > 0.0)) return false;
  center = centroid + Point(-0.5 * c[0], -0.5 * c[1]);
  r = std::sqrt(r2);
  return true;
}

}  // namespace

ContactShape contact_shape(const Mesh& mesh, const ContactResult& contact) {
  ContactShape shape;
  std::set<int> vertices;
  for (const auto& e : contact.edges)
    for (int v : mesh.edge(e.edge)) vertices.insert(v);
  if (vertices.empty()) return shape;
  std::vector<Point> p;
  Point centroid = Point::Zero();
  for (int v : vertices) p.push_back(mesh.vertex(v)), centroid += mesh.vertex(v);
  centroid /= static_cast<double>(p.size());
  double extent = 0.0;
  for (const Point& q : p) extent = std::max(extent, (q - centroid).norm());
  const double tolerance = 1e-6 * extent;
  if (line_deviation(p, centroid) <= tolerance) {
    shape.kind = ContactShape::Kind::kLine;
    return shape;
  }
  shape.kind = ContactShape::Kind::kOther;
  Point center;
  double r = 0.0;
  if (p.size() < 4 || !fit_circle(p, centroid, center, r)) return shape;
  for (const Point& q : p)
    if (std::abs((q - center).norm() - r) > tolerance) return shape;
  shape.kind = ContactShape::Kind::kArc;
  shape.center = center;
  shape.radius = r;
  return shape;
}

}  // namespace fosls
