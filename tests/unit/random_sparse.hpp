#pragma once
// A reproducible random sparse matrix for the unit tests of sparse-matrix building blocks
// (sparse_sum, the truncated prolongation).

#include <random>
#include <vector>

#include "core/box_qp.hpp"

namespace fosls::testing {

/// rows × cols with each entry present with probability `density`, values in [−½, ½),
/// compressed; the same matrix for the same seed.
inline SparseMatrix random_sparse(int rows, int cols, double density, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
      if (u(rng) < density) t.emplace_back(i, j, u(rng) - 0.5);
  SparseMatrix m(rows, cols);
  m.setFromTriplets(t.begin(), t.end());
  m.makeCompressed();
  return m;
}

}  // namespace fosls::testing
