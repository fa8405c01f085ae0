#pragma once
// The held-rows systems of pdas (solvers/pdas_step.hpp) for any active set from one sparse
// factorisation per problem. The bounded DOFs B (the only ones an active set can hold) are
// ordered last, so the trailing block L_BB of the Cholesky factor of A is the factor of their
// Schur complement S = A_BB − A_BI A_II⁻¹ A_IB, and (A⁻¹)_BB = S⁻¹ = L_BB⁻ᵀ L_BB⁻¹ is a small
// dense matrix G. The system "A x = b on the free DOFs, x_H = ψ_H on the held set H" is then
//   x = A⁻¹ (b − E_H μ),   G_HH μ = (A⁻¹ b)_H − ψ_H
// (μ the multipliers of the held rows): two solves with the one factor and a dense Cholesky
// factorisation of G_HH, instead of a new sparse factorisation per active set.
// Worth it where the sparse factorisation costs much more than |B|³ (3D: the contact surface's
// DOFs are a few thousand of several 10⁵); pdas_step.cpp says where it is used. Failures as in
// cholmod_checks.hpp: an out-of-memory status becomes std::bad_alloc.

#include <cholmod.h>

#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

class BoundedComplementSolver {
 public:
  /// The solver for A (symmetric positive definite, both triangles stored) and the bounded DOFs
  /// `bounded`, or null where it does not apply or pay: a factorisation of A of fewer than
  /// `min_flops` (CHOLMOD's count from the analysis), |B|³ above a tenth of that count or |B|²
  /// above the factor's entries, A not positive definite, or the bounded DOFs not last in the
  /// postordered factor. The caller then
  /// factorises per active set, as before.
  static std::unique_ptr<BoundedComplementSolver> make(const SparseMatrix& a,
                                                       const std::vector<int>& bounded,
                                                       double min_flops);
  ~BoundedComplementSolver();
  BoundedComplementSolver(const BoundedComplementSolver&) = delete;
  BoundedComplementSolver& operator=(const BoundedComplementSolver&) = delete;

  /// x with x_i = psi[i] where held[i] and A x = b in the other rows. False, x unchanged, when
  /// a held DOF is not bounded or G_HH is not numerically positive definite.
  bool solve(const std::vector<char>& held, const Vector& b, const Vector& psi, Vector& x);

 private:
  BoundedComplementSolver() = default;
  /// Orders A with CHOLMOD's default methods, then again with the bounded DOFs moved last;
  /// false when the postordered factor does not keep them last.
  bool analyse(const SparseMatrix& a, const std::vector<int>& bounded, double min_flops);
  /// G = L_BB⁻ᵀ L_BB⁻¹ from the trailing block of the supernodal factor.
  void invert_complement();
  /// A⁻¹ b with the factor.
  Vector solve_full(const Vector& b);

  cholmod_common common_;
  bool started_ = false;
  cholmod_factor* factor_ = nullptr;
  int first_bounded_ = 0;               // the factor's position of the first bounded DOF
  std::vector<int> slot_;               // DOF → its position in G, −1 for unbounded DOFs
  Eigen::MatrixXd complement_inverse_;  // G = (A⁻¹)_BB, in the factor's order
};

}  // namespace fosls
