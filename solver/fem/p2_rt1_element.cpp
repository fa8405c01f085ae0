#include "fem/p2_rt1_element.hpp"

#include <Eigen/LU>
#include <cmath>

namespace fosls {

const std::array<TrianglePoint, 7> kTriangleDegree5 = {{
    {1.0 / 3.0, 1.0 / 3.0, 0.225},
    {0.0597158717897698, 0.4701420641051151, 0.1323941527885062},
    {0.4701420641051151, 0.0597158717897698, 0.1323941527885062},
    {0.4701420641051151, 0.4701420641051151, 0.1323941527885062},
    {0.7974269853530873, 0.1012865073234563, 0.1259391805448271},
    {0.1012865073234563, 0.7974269853530873, 0.1259391805448271},
    {0.1012865073234563, 0.1012865073234563, 0.1259391805448271},
}};

P2Rt1Element::P2Rt1Element(const Mesh& mesh, int t) {
  const auto& tri = mesh.triangle(t);
  for (int k = 0; k < 3; ++k) a_[k] = mesh.vertex(tri[k]);
  area_ = mesh.triangle_area(t);
  centre_ = (a_[0] + a_[1] + a_[2]) / 3.0;
  scale_ = std::sqrt(2.0 * area_);
  for (int k = 0; k < 3; ++k) {
    const Point& p = a_[(k + 1) % 3];
    const Point& q = a_[(k + 2) % 3];
    grad_lambda_[k] = Point(p.y() - q.y(), q.x() - p.x()) / (2.0 * area_);
  }
  // The functionals applied to the monomials; the basis is its inverse.
  Eigen::Matrix<double, 8, 8> v;
  for (int k = 0; k < 3; ++k) {
    const int e = mesh.triangle_edge(t, k);
    const Point n = mesh.edge_normal(e);
    const double half = 0.5 * mesh.edge_length(e);
    for (int j = 0; j < 2; ++j) {
      const auto q = monomials(mesh.vertex(mesh.edge(e)[j]));
      for (int m = 0; m < 8; ++m) v(2 * k + j, m) = half * q[m].dot(n);
    }
  }
  v.row(6).setZero();
  v.row(7).setZero();
  for (int k = 0; k < 3; ++k) {  // the edge-midpoint rule is exact for the degree-2 fields
    const auto q = monomials(0.5 * (a_[(k + 1) % 3] + a_[(k + 2) % 3]));
    for (int m = 0; m < 8; ++m) {
      v(6, m) += q[m].x() / 3.0;
      v(7, m) += q[m].y() / 3.0;
    }
  }
  coefficients_ = v.inverse();
}

Point P2Rt1Element::point(double l0, double l1) const {
  return l0 * a_[0] + l1 * a_[1] + (1.0 - l0 - l1) * a_[2];
}

Eigen::Vector3d P2Rt1Element::barycentric(const Point& x) const {
  Eigen::Vector3d l;
  for (int k = 0; k < 3; ++k) l[k] = 1.0 + grad_lambda_[k].dot(x - a_[k]);
  return l;
}

std::array<double, 6> P2Rt1Element::p2(const Point& x) const {
  const Eigen::Vector3d l = barycentric(x);
  std::array<double, 6> v;
  for (int k = 0; k < 3; ++k) {
    v[k] = l[k] * (2.0 * l[k] - 1.0);
    v[3 + k] = 4.0 * l[(k + 1) % 3] * l[(k + 2) % 3];
  }
  return v;
}

std::array<Point, 6> P2Rt1Element::p2_gradients(const Point& x) const {
  const Eigen::Vector3d l = barycentric(x);
  std::array<Point, 6> g;
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    g[k] = (4.0 * l[k] - 1.0) * grad_lambda_[k];
    g[3 + k] = 4.0 * (l[k1] * grad_lambda_[k2] + l[k2] * grad_lambda_[k1]);
  }
  return g;
}

std::array<Point, 8> P2Rt1Element::monomials(const Point& x) const {
  const double s = (x.x() - centre_.x()) / scale_, r = (x.y() - centre_.y()) / scale_;
  return {Point(1, 0), Point(0, 1), Point(s, 0),         Point(r, 0),
          Point(0, s), Point(0, r), Point(s * s, s * r), Point(s * r, r * r)};
}

std::array<double, 8> P2Rt1Element::monomial_divergences(const Point& x) const {
  const double s = (x.x() - centre_.x()) / scale_, r = (x.y() - centre_.y()) / scale_;
  const double h = 1.0 / scale_;
  return {0.0, 0.0, h, 0.0, 0.0, h, 3.0 * s * h, 3.0 * r * h};
}

std::array<Point, 8> P2Rt1Element::rt1(const Point& x) const {
  const auto q = monomials(x);
  std::array<Point, 8> psi;
  for (int m = 0; m < 8; ++m) {
    psi[m].setZero();
    for (int n = 0; n < 8; ++n) psi[m] += coefficients_(n, m) * q[n];
  }
  return psi;
}

std::array<double, 8> P2Rt1Element::rt1_divergences(const Point& x) const {
  const auto d = monomial_divergences(x);
  std::array<double, 8> div;
  for (int m = 0; m < 8; ++m) {
    div[m] = 0.0;
    for (int n = 0; n < 8; ++n) div[m] += coefficients_(n, m) * d[n];
  }
  return div;
}

}  // namespace fosls
