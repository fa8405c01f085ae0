#pragma once
// A monotone smoother: successive exact minimisation of J over small subspaces within the
// bounds (docs/method.md §4.1), on x and the residual r = b − A x, kept up to date. The ones a
// case can choose are in smoother_table.hpp; the contact-strip solve (strip_smoother.hpp) runs
// after every sweep of the chosen one.

#include "core/box_qp.hpp"

namespace fosls {

class Smoother {
 public:
  virtual ~Smoother() = default;
  /// One sweep within [lo, hi], forwards or backwards (a symmetric pair: forward before the
  /// coarse correction, backward after). J(x) does not increase and x stays within the bounds.
  virtual void sweep(Vector& x, Vector& r, const Vector& lo, const Vector& hi,
                     bool forward) const = 0;
  /// Whether the smoother had to keep local factors in double precision
  /// (small_cholesky_factors.hpp): counted in CycleStatistics.
  virtual bool double_precision_factors() const { return false; }
};

/// Subtracts A[:, j] · d from r (the residual update after x_j changed by d).
inline void update_residual(const SparseMatrix& A, int j, double d, Vector& r) {
  for (SparseMatrix::InnerIterator it(A, j); it; ++it) r[it.row()] -= it.value() * d;
}

}  // namespace fosls
