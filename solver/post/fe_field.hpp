#pragma once
// Point evaluation of a discrete solution (u_h, σ_h) and error norms against exact fields.

#include <Eigen/Core>
#include <array>
#include <functional>

#include "core/box_qp.hpp"
#include "fem/fosls_space.hpp"

namespace fosls {

/// A discrete solution in Cartesian coordinates with physical (unscaled) stresses.
class FeField {
 public:
  /// `x_full` is the full DOF vector in the space's rotated coordinates with scaled stresses.
  FeField(const FoslsSpace<2>& space, const Vector& x_full, double stress_scale);

  Eigen::Vector2d u(int t, const Point& x) const;
  /// ∇u as a matrix (row i = ∇u_i).
  Eigen::Matrix2d grad_u(int t, const Point& x) const;
  /// σ (row i = σ_i).
  Eigen::Matrix2d sigma(int t, const Point& x) const;
  Eigen::Vector2d div_sigma(int t) const;
  /// Cartesian value of a DOF (u_c at a vertex, flux of σ_i through an edge).
  double cartesian(int dof) const { return x_[dof]; }
  const FoslsSpace<2>& space() const { return space_; }

 private:
  const FoslsSpace<2>& space_;
  Vector x_;
};

/// The exact solution of a verification problem.
struct ExactSolution {
  std::function<Eigen::Vector2d(const Point&)> u;
  std::function<Eigen::Matrix2d(const Point&)> grad_u;
  std::function<Eigen::Matrix2d(const Point&)> sigma;
  std::function<Eigen::Vector2d(const Point&)> div_sigma;
};

struct ErrorNorms {
  double u_l2 = 0, u_h1 = 0;            ///< ‖u − u_h‖_L2, ‖u − u_h‖_H1
  double sigma_l2 = 0, sigma_hdiv = 0;  ///< ‖σ − σ_h‖_L2, ‖σ − σ_h‖_H(div)
};

/// Squared errors of one triangle by a 7-point quadrature of degree 5:
/// ‖u − u_h‖², ‖∇(u − u_h)‖², ‖σ − σ_h‖², ‖div(σ − σ_h)‖² on T.
std::array<double, 4> element_error(const FeField& field, const ExactSolution& exact, int t);

/// The element errors summed over the mesh.
ErrorNorms error_norms(const FeField& field, const ExactSolution& exact);

}  // namespace fosls
