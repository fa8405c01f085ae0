#pragma once
// Edits of a sparse matrix's stored values that can be undone exactly. The multilevel cycle
// forms the truncated matrix of the second-finest level in the storage of the untruncated
// Galerkin matrix (the truncation changes only entries already in its pattern), and writes the
// saved values back before the next active set or when the solve ends: one matrix of that size
// instead of two, the largest coarse matrix of a solve (docs/performance.md).

#include <cstddef>
#include <utility>
#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

class ReversibleEdits {
 public:
  explicit ReversibleEdits(SparseMatrix& matrix) : matrix_(&matrix) {}
  /// Saves the current value of an entry of the matrix (a pointer into its value array) before
  /// the caller changes it.
  void save(double* value) { saved_.emplace_back(value - matrix_->valuePtr(), *value); }
  /// Adds `c` to the matrix if every entry of `c` is in the matrix's pattern (saving what it
  /// changes) and returns true; else changes nothing and returns false.
  bool add_within_pattern(const SparseMatrix& c);
  /// Writes every saved value back, newest first, so each entry gets its value from before the
  /// first edit.
  void restore();
  SparseMatrix& matrix() { return *matrix_; }

 private:
  SparseMatrix* matrix_;
  std::vector<std::pair<std::ptrdiff_t, double>> saved_;
};

}  // namespace fosls
