#pragma once
// The FOSLS functional's operators on one simplex (docs/method.md §2–3, §11), acting on the
// cell's local DOFs in FoslsSpace<dim>::cell_dofs order (u: d·k + c, σ: d(d + 1) + d·k + i), in
// Cartesian coordinates with μ = 1 (scaled stresses). Written once for triangles and tetrahedra.

#include <Eigen/Core>
#include <cmath>

#include "fem/simplex_element.hpp"

namespace fosls {

template <int dim>
constexpr int kLocalDofs = 2 * dim*(dim + 1);

/// The operators of one cell at one point.
template <int dim>
struct PointOperators {
  /// Rows d·i + j: (Aσ − ε(u))_ij.
  Eigen::Matrix<double, dim * dim, kLocalDofs<dim>> constitutive;
  /// One row per pair i < j: σ_ij − σ_ji (one in 2D, three in 3D).
  Eigen::Matrix<double, dim*(dim - 1) / 2, kLocalDofs<dim>> asymmetry;
};

/// Aσ − ε(u) and as σ at x: Aσ = (σ − κ tr σ I)/(2μ), σ_ij = Σ_k S_{i,k} ψ_k,j, and
/// −ε_ij = −½(∂_j u_i + ∂_i u_j).
template <int dim>
PointOperators<dim> point_operators(const SimplexElement<dim>& e, const Vec<dim>& x, double kappa) {
  constexpr int s0 = dim * (dim + 1);
  PointOperators<dim> op;
  op.constitutive.setZero();
  op.asymmetry.setZero();
  for (int k = 0; k <= dim; ++k) {
    const Vec<dim> psi = e.rt0(k, x);
    const Vec<dim> grad = e.grad_p1(k);
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) {
        op.constitutive(dim * i + j, s0 + dim * k + i) += 0.5 * psi[j];
        if (i == j)
          for (int m = 0; m < dim; ++m)
            op.constitutive((dim + 1) * i, s0 + dim * k + m) -= 0.5 * kappa * psi[m];
        op.constitutive(dim * i + j, dim * k + i) -= 0.5 * grad[j];
        op.constitutive(dim * i + j, dim * k + j) -= 0.5 * grad[i];
      }
    int pair = 0;
    for (int i = 0; i < dim; ++i)
      for (int j = i + 1; j < dim; ++j, ++pair) {
        op.asymmetry(pair, s0 + dim * k + i) += psi[j];
        op.asymmetry(pair, s0 + dim * k + j) -= psi[i];
      }
  }
  return op;
}

/// tr(Aσ − ε(u)) at a point: the volumetric part of the constitutive residual, whose square the
/// c2 term weights by 1/d (the Frobenius norm) and `c2_volumetric` re-weights.
template <int dim>
Eigen::Matrix<double, 1, kLocalDofs<dim>> volumetric_row(const PointOperators<dim>& op) {
  Eigen::Matrix<double, 1, kLocalDofs<dim>> trace = op.constitutive.row(0);
  for (int i = 1; i < dim; ++i) trace += op.constitutive.row((dim + 1) * i);
  return trace;
}

/// |as σ|² at a point for the local DOF values xl.
template <int dim>
double asymmetry_square(const PointOperators<dim>& op,
                        const Eigen::Matrix<double, kLocalDofs<dim>, 1>& xl) {
  if constexpr (dim == 2)
    return std::pow(op.asymmetry.dot(xl), 2);
  else
    return (op.asymmetry * xl).squaredNorm();
}

/// div σ_i as a function of the local DOFs (constant on the cell).
template <int dim>
Eigen::Matrix<double, dim, kLocalDofs<dim>> divergence_operator(const SimplexElement<dim>& e) {
  Eigen::Matrix<double, dim, kLocalDofs<dim>> d;
  d.setZero();
  for (int k = 0; k <= dim; ++k)
    for (int i = 0; i < dim; ++i) d(i, dim * (dim + 1) + dim * k + i) = e.rt0_div(k);
  return d;
}

}  // namespace fosls
