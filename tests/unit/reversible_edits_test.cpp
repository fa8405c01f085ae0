// ReversibleEdits: the truncated coarse matrix formed in the storage of the untruncated one
// must come back bit for bit.
#include "solvers/reversible_edits.hpp"

#include <gtest/gtest.h>

namespace fosls {
namespace {

SparseMatrix tridiagonal(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + 0.1 * i);
    if (i > 0) t.emplace_back(i, i - 1, -1.0 / 3.0), t.emplace_back(i - 1, i, -1.0 / 3.0);
  }
  SparseMatrix m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  m.makeCompressed();
  return m;
}

TEST(ReversibleEdits, AddsWithinThePatternAndRestoresExactly) {
  SparseMatrix m = tridiagonal(6);
  const SparseMatrix original = m;
  ReversibleEdits edits(m);
  SparseMatrix c(6, 6);
  c.insert(2, 2) = 0.7;
  c.insert(3, 2) = 1e-17;
  c.makeCompressed();
  ASSERT_TRUE(edits.add_within_pattern(c));
  EXPECT_EQ(m.coeff(2, 2), original.coeff(2, 2) + 0.7);
  EXPECT_EQ(m.coeff(3, 2), original.coeff(3, 2) + 1e-17);
  // A second edit of the same entry, as the diagonal shift after the correction.
  for (SparseMatrix::InnerIterator it(m, 2); it; ++it)
    if (it.row() == 2) edits.save(&it.valueRef()), it.valueRef() *= 3.0;
  EXPECT_TRUE(edits.add_within_pattern(c));
  edits.restore();
  EXPECT_EQ(m.nonZeros(), original.nonZeros());
  for (int k = 0; k < m.nonZeros(); ++k) EXPECT_EQ(m.valuePtr()[k], original.valuePtr()[k]);
}

TEST(ReversibleEdits, RefusesEntriesOutsideThePatternWithoutChangingAnything) {
  SparseMatrix m = tridiagonal(5);
  const SparseMatrix original = m;
  ReversibleEdits edits(m);
  SparseMatrix c(5, 5);
  c.insert(1, 1) = 1.0;  // inside
  c.insert(4, 0) = 1.0;  // outside
  c.makeCompressed();
  EXPECT_FALSE(edits.add_within_pattern(c));
  for (int k = 0; k < m.nonZeros(); ++k) EXPECT_EQ(m.valuePtr()[k], original.valuePtr()[k]);
}

}  // namespace
}  // namespace fosls
