#include "post/fe_field.hpp"

#include <cmath>

#include "fem/element_geometry.hpp"

namespace fosls {

FeField::FeField(const FoslsSpace& space, const Vector& x_full, double stress_scale)
    : space_(space), x_(space.rotation() * x_full) {
  const int nu = 2 * space.mesh().num_vertices();
  x_.tail(x_.size() - nu) *= stress_scale;
}

Eigen::Vector2d FeField::u(int t, const Point& x) const {
  ElementGeometry g(space_.mesh(), t);
  Eigen::Vector2d v = Eigen::Vector2d::Zero();
  for (int k = 0; k < 3; ++k) {
    int vert = space_.mesh().triangle(t)[k];
    double phi = g.p1(k, x);
    for (int c = 0; c < 2; ++c) v[c] += phi * x_[space_.u_dof(vert, c)];
  }
  return v;
}

Eigen::Matrix2d FeField::grad_u(int t, const Point&) const {
  ElementGeometry g(space_.mesh(), t);
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  for (int k = 0; k < 3; ++k) {
    int vert = space_.mesh().triangle(t)[k];
    for (int c = 0; c < 2; ++c) m.row(c) += x_[space_.u_dof(vert, c)] * g.grad_p1(k).transpose();
  }
  return m;
}

Eigen::Matrix2d FeField::sigma(int t, const Point& x) const {
  ElementGeometry g(space_.mesh(), t);
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  for (int k = 0; k < 3; ++k) {
    int e = space_.mesh().triangle_edge(t, k);
    for (int i = 0; i < 2; ++i) m.row(i) += x_[space_.sigma_dof(e, i)] * g.rt0(k, x).transpose();
  }
  return m;
}

Eigen::Vector2d FeField::div_sigma(int t) const {
  ElementGeometry g(space_.mesh(), t);
  Eigen::Vector2d d = Eigen::Vector2d::Zero();
  for (int k = 0; k < 3; ++k) {
    int e = space_.mesh().triangle_edge(t, k);
    for (int i = 0; i < 2; ++i) d[i] += x_[space_.sigma_dof(e, i)] * g.rt0_div(k);
  }
  return d;
}

ErrorNorms error_norms(const FeField& field, const ExactSolution& exact) {
  // Dunavant degree-5 rule: barycentric points and weights (sum 1).
  static const double a1 = 0.059715871789770, b1 = 0.470142064105115;
  static const double a2 = 0.797426985353087, b2 = 0.101286507323456;
  static const double bary[7][3] = {{1. / 3, 1. / 3, 1. / 3},
                                    {a1, b1, b1},
                                    {b1, a1, b1},
                                    {b1, b1, a1},
                                    {a2, b2, b2},
                                    {b2, a2, b2},
                                    {b2, b2, a2}};
  static const double w[7] = {0.225,
                              0.132394152788506,
                              0.132394152788506,
                              0.132394152788506,
                              0.125939180544827,
                              0.125939180544827,
                              0.125939180544827};
  const Mesh& mesh = field.space().mesh();
  double ul2 = 0, ugrad = 0, sl2 = 0, sdiv = 0;
#pragma omp parallel for reduction(+ : ul2, ugrad, sl2, sdiv) schedule(static)
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangle(t);
    const double area = mesh.triangle_area(t);
    const Eigen::Vector2d divh = field.div_sigma(t);
    const Eigen::Matrix2d gradh = field.grad_u(t, Point::Zero());
    for (int q = 0; q < 7; ++q) {
      Point x = bary[q][0] * mesh.vertex(tri[0]) + bary[q][1] * mesh.vertex(tri[1]) +
                bary[q][2] * mesh.vertex(tri[2]);
      const double wq = w[q] * area;
      ul2 += wq * (exact.u(x) - field.u(t, x)).squaredNorm();
      ugrad += wq * (exact.grad_u(x) - gradh).squaredNorm();
      sl2 += wq * (exact.sigma(x) - field.sigma(t, x)).squaredNorm();
      sdiv += wq * (exact.div_sigma(x) - divh).squaredNorm();
    }
  }
  ErrorNorms e;
  e.u_l2 = std::sqrt(ul2);
  e.u_h1 = std::sqrt(ul2 + ugrad);
  e.sigma_l2 = std::sqrt(sl2);
  e.sigma_hdiv = std::sqrt(sl2 + sdiv);
  return e;
}

}  // namespace fosls
