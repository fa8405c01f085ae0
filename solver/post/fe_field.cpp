#include "post/fe_field.hpp"

#include <cmath>

#include "fem/simplex_element.hpp"

namespace fosls {

FeField::FeField(const FoslsSpace<2>& space, const Vector& x_full, double stress_scale)
    : space_(space), x_(space.rotation() * x_full) {
  const int nu = 2 * space.mesh().num_vertices();
  x_.tail(x_.size() - nu) *= stress_scale;
}

Eigen::Vector2d FeField::u(int t, const Point& x) const {
  const SimplexElement<2> g(space_.mesh(), t);
  Eigen::Vector2d v = Eigen::Vector2d::Zero();
  for (int k = 0; k < 3; ++k) {
    int vert = space_.mesh().triangle(t)[k];
    double phi = g.p1(k, x);
    for (int c = 0; c < 2; ++c) v[c] += phi * x_[space_.u_dof(vert, c)];
  }
  return v;
}

Eigen::Matrix2d FeField::grad_u(int t, const Point&) const {
  const SimplexElement<2> g(space_.mesh(), t);
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  for (int k = 0; k < 3; ++k) {
    int vert = space_.mesh().triangle(t)[k];
    for (int c = 0; c < 2; ++c) m.row(c) += x_[space_.u_dof(vert, c)] * g.grad_p1(k).transpose();
  }
  return m;
}

Eigen::Matrix2d FeField::sigma(int t, const Point& x) const {
  const SimplexElement<2> g(space_.mesh(), t);
  Eigen::Matrix2d m = Eigen::Matrix2d::Zero();
  for (int k = 0; k < 3; ++k) {
    int e = space_.mesh().triangle_edge(t, k);
    for (int i = 0; i < 2; ++i) m.row(i) += x_[space_.sigma_dof(e, i)] * g.rt0(k, x).transpose();
  }
  return m;
}

Eigen::Vector2d FeField::div_sigma(int t) const {
  const SimplexElement<2> g(space_.mesh(), t);
  Eigen::Vector2d d = Eigen::Vector2d::Zero();
  for (int k = 0; k < 3; ++k) {
    int e = space_.mesh().triangle_edge(t, k);
    for (int i = 0; i < 2; ++i) d[i] += x_[space_.sigma_dof(e, i)] * g.rt0_div(k);
  }
  return d;
}

namespace {
// Dunavant degree-5 rule: barycentric points and weights (sum 1).
constexpr double kA1 = 0.059715871789770, kB1 = 0.470142064105115;
constexpr double kA2 = 0.797426985353087, kB2 = 0.101286507323456;
constexpr double kBary[7][3] = {{1. / 3, 1. / 3, 1. / 3}, {kA1, kB1, kB1}, {kB1, kA1, kB1},
                                {kB1, kB1, kA1},          {kA2, kB2, kB2}, {kB2, kA2, kB2},
                                {kB2, kB2, kA2}};
constexpr double kWeight[7] = {0.225,
                               0.132394152788506,
                               0.132394152788506,
                               0.132394152788506,
                               0.125939180544827,
                               0.125939180544827,
                               0.125939180544827};
}  // namespace

std::array<double, 4> element_error(const FeField& field, const ExactSolution& exact, int t) {
  const Mesh& mesh = field.space().mesh();
  const auto& tri = mesh.triangle(t);
  const double area = mesh.triangle_area(t);
  const Eigen::Vector2d divh = field.div_sigma(t);
  const Eigen::Matrix2d gradh = field.grad_u(t, Point::Zero());
  std::array<double, 4> e = {0, 0, 0, 0};
  for (int q = 0; q < 7; ++q) {
    const Point x = kBary[q][0] * mesh.vertex(tri[0]) + kBary[q][1] * mesh.vertex(tri[1]) +
                    kBary[q][2] * mesh.vertex(tri[2]);
    const double w = kWeight[q] * area;
    e[0] += w * (exact.u(x) - field.u(t, x)).squaredNorm();
    e[1] += w * (exact.grad_u(x) - gradh).squaredNorm();
    e[2] += w * (exact.sigma(x) - field.sigma(t, x)).squaredNorm();
    e[3] += w * (exact.div_sigma(x) - divh).squaredNorm();
  }
  return e;
}

ErrorNorms error_norms(const FeField& field, const ExactSolution& exact) {
  const Mesh& mesh = field.space().mesh();
  double ul2 = 0, ugrad = 0, sl2 = 0, sdiv = 0;
#pragma omp parallel for reduction(+ : ul2, ugrad, sl2, sdiv) schedule(static)
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto e = element_error(field, exact, t);
    ul2 += e[0], ugrad += e[1], sl2 += e[2], sdiv += e[3];
  }
  ErrorNorms e;
  e.u_l2 = std::sqrt(ul2);
  e.u_h1 = std::sqrt(ul2 + ugrad);
  e.sigma_l2 = std::sqrt(sl2);
  e.sigma_hdiv = std::sqrt(sl2 + sdiv);
  return e;
}

}  // namespace fosls
