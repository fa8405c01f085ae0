#pragma once
// The Cholesky factors of many small symmetric positive definite matrices (the vertex patches
// of a level), packed: only the lower triangle, by columns, one after another. They were the
// largest part of a multilevel solve after A itself.
//
// They are kept in single precision when that is safe, which halves them. A factor L_f rounded
// from the exact L is the exact factor of Ã = L_f L_fᵀ, so a local solve with it minimises the
// quadratic with Ã in place of the patch matrix A_p = L Lᵀ. With ε = ‖L⁻¹(Ã − A_p)L⁻ᵀ‖₂ < ½ such
// a correction d still decreases J: for the minimiser over a box around 0, rᵀd ≥ dᵀÃd, and
// dᵀÃd ≥ (1 − ε) dᵀA_p d, so ½dᵀA_p d − rᵀd ≤ −½(1 − 2ε) dᵀA_p d < 0 (docs/method.md §4.1).
// The residual stays in double, so the accuracy the iteration reaches does not change; only the
// local solves are inexact, by ε. ε is bounded for every matrix (rounding_bound); if one bound
// exceeds kMaxSinglePerturbation, all factors are kept in double; the bounds met stay far below
// it up to the case limit (docs/performance.md, "Measurements behind choices in the code").

#include <Eigen/Dense>
#include <cstddef>
#include <functional>
#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

class SmallCholeskyFactors {
 public:
  /// Largest bound on ε for which the factors are kept in single precision: far inside ½, so
  /// that a step keeps at least 98 % of ½dᵀA_p d as decrease of J (the bound above).
  static constexpr double kMaxSinglePerturbation = 1e-2;

  /// `fill(k, block)` writes matrix k, of order sizes[k], into `block` (already sized, zero);
  /// called from several threads at once. Returns the index of the first matrix found not
  /// positive definite in `failed` (−1 when all are).
  SmallCholeskyFactors(const std::vector<int>& sizes,
                       const std::function<void(int, Eigen::MatrixXd&)>& fill, int& failed);

  /// Solves Ã_k y = y in place with the stored factor (Ã_k = A_k when kept in double).
  void solve(int k, Vector& y) const;
  /// Bound on ε = ‖L⁻¹(L_f L_fᵀ − L Lᵀ)L⁻ᵀ‖₂ for the exact lower factor L and L_f = L rounded
  /// to float: 2‖G‖_F + ‖G‖_F² with G = L⁻¹(L_f − L).
  static double rounding_bound(const Eigen::MatrixXd& l);
  /// The stored lower factor of matrix k, as a dense matrix.
  Eigen::MatrixXd lower(int k) const;

  /// False when a bound exceeded kMaxSinglePerturbation (counted in the solver statistics).
  bool single_precision() const { return single_precision_; }
  /// Storage of the factors in bytes.
  std::size_t bytes() const {
    return single_.size() * sizeof(float) + double_.size() * sizeof(double);
  }

 private:
  /// Factorises every matrix into the storage of type T; returns false if single precision
  /// was asked for and a bound exceeded kMaxSinglePerturbation.
  template <typename T>
  bool factorise(const std::vector<int>& sizes,
                 const std::function<void(int, Eigen::MatrixXd&)>& fill, std::vector<T>& out,
                 int& failed);

  std::vector<std::size_t> offset_;  ///< start of each factor
  std::vector<int> order_;           ///< order of each matrix
  bool single_precision_ = true;
  std::vector<float> single_;   ///< the factors, when kept in single precision
  std::vector<double> double_;  ///< otherwise
};

}  // namespace fosls
