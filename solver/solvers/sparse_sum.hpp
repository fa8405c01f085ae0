#pragma once
// Sums of sparse matrices into storage of exactly the size of the result. Eigen's `a + b`
// (and `a += b`) evaluates a sum through a temporary that grows by reallocation, so a coarse
// matrix updated that way briefly needed up to three times its own size: the peak memory of a
// multilevel solve was reached there, once per new active set (docs/performance.md).

#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

/// a + b (same shape, column-major, compressed). Entries of `a` in the rows with
/// `dropped_rows[i] != 0` are left out when `dropped_rows` is given: the truncated
/// prolongation is P without its truncated rows plus a few corrections. Counts the result's
/// entries column by column first, then fills: no reallocation, rows sorted.
SparseMatrix sparse_sum(const SparseMatrix& a, const SparseMatrix& b,
                        const std::vector<char>* dropped_rows = nullptr);

}  // namespace fosls
