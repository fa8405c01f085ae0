#pragma once
// Pointwise projected (non-linear) Gauss–Seidel: x_i ← clamp(x_i + r_i / A_ii).

#include "solvers/smoother.hpp"

namespace fosls {

class PointSmoother : public Smoother {
 public:
  explicit PointSmoother(const SparseMatrix& A);
  void sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi, bool forward) const override;

 private:
  const SparseMatrix& A_;
  Vector diagonal_;
};

}  // namespace fosls
