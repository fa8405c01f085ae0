#include "displacement_elements.hpp"

#include <cmath>

namespace fosls {

namespace {

/// ∇N_i = R(opposite edge) / (2A), R the rotation by +90° of (x_{i+2} − x_{i+1}), A the signed
/// area (so either orientation gives the gradients).
std::array<Point, 3> hat_gradients(const std::array<Point, 3>& x, double area) {
  std::array<Point, 3> grad;
  for (int i = 0; i < 3; ++i) {
    const Point e = x[(i + 2) % 3] - x[(i + 1) % 3];
    grad[i] = Point(-e.y(), e.x()) / (2.0 * area);
  }
  return grad;
}

double signed_area(const std::array<Point, 3>& x) {
  const Point a = x[1] - x[0], b = x[2] - x[0];
  return 0.5 * (a.x() * b.y() - a.y() * b.x());
}

}  // namespace

ElementMatrices plane_strain_element(const ElementData& e) {
  const double area = std::abs(signed_area(e.x));
  const auto grad = hat_gradients(e.x, signed_area(e.x));
  // B-matrix rows: ε_xx, ε_yy, 2ε_xy.
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  Eigen::Matrix<double, 1, 6> div;
  for (int i = 0; i < 3; ++i) {
    B(0, 2 * i) = grad[i].x();
    B(1, 2 * i + 1) = grad[i].y();
    B(2, 2 * i) = grad[i].y();
    B(2, 2 * i + 1) = grad[i].x();
    div(2 * i) = grad[i].x();
    div(2 * i + 1) = grad[i].y();
  }
  const Eigen::Vector3d D(2 * e.mu, 2 * e.mu, e.mu);  // 2μ ε:ε in Voigt form
  ElementMatrices m;
  m.stiffness =
      area * (B.transpose() * D.asDiagonal() * B + e.lambda_in_stiffness * div.transpose() * div);
  // div v is constant on T and N_i linear: ∫_T N_i div v = |T|/3 div v.
  for (int i = 0; i < 3; ++i) m.coupling.row(i) = area / 3 * div;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.mass(i, j) = area / 12 * (i == j ? 2.0 : 1.0);
  for (int i = 0; i < 3; ++i) {
    m.load[2 * i] = area / 3 * e.body_force.x();
    m.load[2 * i + 1] = area / 3 * e.body_force.y();
  }
  return m;
}

ElementMatrices axisymmetric_element(const ElementData& e) {
  const double area = std::abs(signed_area(e.x));
  const auto grad = hat_gradients(e.x, signed_area(e.x));
  // Strains of a body of revolution: ε_rr, ε_zz, ε_θθ = u_r / r, 2ε_rz. The hoop strain is not
  // polynomial; the three interior points (barycentric 2/3, 1/6, 1/6) keep r > 0 at every
  // quadrature point, also on triangles that touch the axis.
  const Eigen::Vector4d D(2 * e.mu, 2 * e.mu, 2 * e.mu, e.mu);
  ElementMatrices m;
  m.stiffness.setZero();
  m.coupling.setZero();
  m.mass.setZero();
  m.load.setZero();
  for (int q = 0; q < 3; ++q) {
    Eigen::Vector3d N = Eigen::Vector3d::Constant(1.0 / 6.0);
    N[q] = 2.0 / 3.0;
    const Point xq = N[0] * e.x[0] + N[1] * e.x[1] + N[2] * e.x[2];
    const double r = xq.x(), weight = area / 3 * 2 * M_PI * r;
    Eigen::Matrix<double, 4, 6> B = Eigen::Matrix<double, 4, 6>::Zero();
    Eigen::Matrix<double, 1, 6> div;
    for (int i = 0; i < 3; ++i) {
      B(0, 2 * i) = grad[i].x();
      B(1, 2 * i + 1) = grad[i].y();
      B(2, 2 * i) = N[i] / r;
      B(3, 2 * i) = grad[i].y();
      B(3, 2 * i + 1) = grad[i].x();
      div(2 * i) = grad[i].x() + N[i] / r;
      div(2 * i + 1) = grad[i].y();
    }
    m.stiffness += weight * (B.transpose() * D.asDiagonal() * B +
                             e.lambda_in_stiffness * div.transpose() * div);
    m.coupling += weight * N * div;
    m.mass += weight * N * N.transpose();
    for (int i = 0; i < 3; ++i) {
      m.load[2 * i] += weight * N[i] * e.body_force.x();
      m.load[2 * i + 1] += weight * N[i] * e.body_force.y();
    }
  }
  return m;
}

std::array<double, 2> edge_load_weights(const Point& a, const Point& b, bool axisymmetric) {
  const double length = (b - a).norm();
  if (!axisymmetric) return {length / 2, length / 2};
  // ∫ N_a 2πr ds with r linear along the edge: 2π |e| (2 r_a + r_b) / 6.
  return {2 * M_PI * length * (2 * a.x() + b.x()) / 6, 2 * M_PI * length * (a.x() + 2 * b.x()) / 6};
}

}  // namespace fosls
