#pragma once
// Exact minimisation over the strip of triangles along the contact boundary, within the
// bounds. Where neither U_n nor S_n is at its bound (at the edge of the contact zone) the
// functional only weakly controls the normal boundary data (through c3), so the error has
// modes a few elements wide along the boundary that neither vertex patches nor the coarse
// levels reach; one exact solve on the strip removes them. A monotone subspace step like the
// other smoothers; the multilevel cycle runs it after every sweep (MultilevelOptions::strip).

#include <memory>
#include <vector>

#include "core/level_hierarchy.hpp"
#include "solvers/smoother.hpp"

namespace fosls {

class SparseBoxQpSolver;

class StripSmoother : public Smoother {
 public:
  /// Throws IndefiniteSystemError when the strip's matrix is not positive definite.
  StripSmoother(const SparseMatrix& A, std::vector<int> strip, BlockFactorization factorization);
  ~StripSmoother() override;
  /// The exact solve on the strip (the direction plays no part). The QP solver keeps the
  /// factorisation of the last free set: a cache, which changes no result.
  void sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi, bool forward) const override;

 private:
  const SparseMatrix& A_;
  std::vector<int> strip_;
  std::unique_ptr<SparseBoxQpSolver> solver_;
};

}  // namespace fosls
