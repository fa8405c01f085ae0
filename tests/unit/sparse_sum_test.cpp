// sparse_sum: the exact-size sum that replaces Eigen's growing `a + b` in the multilevel set-up.
#include "solvers/sparse_sum.hpp"

#include <gtest/gtest.h>

#include "random_sparse.hpp"

namespace fosls {
namespace {

using testing::random_sparse;

TEST(SparseSum, EqualsEigensSumWithExactStorage) {
  const SparseMatrix a = random_sparse(60, 40, 0.2, 1), b = random_sparse(60, 40, 0.05, 2);
  const SparseMatrix sum = sparse_sum(a, b);
  const SparseMatrix expected = a + b;
  EXPECT_EQ(Eigen::MatrixXd(sum), Eigen::MatrixXd(expected));
  EXPECT_EQ(sum.nonZeros(), expected.nonZeros());
  EXPECT_TRUE(sum.isCompressed());
  EXPECT_EQ(sum.data().allocatedSize(), sum.nonZeros());  // no spare capacity
  for (int col = 0; col < sum.outerSize(); ++col) {
    int previous = -1;
    for (SparseMatrix::InnerIterator it(sum, col); it; ++it) {
      EXPECT_GT(it.row(), previous);
      previous = static_cast<int>(it.row());
    }
  }
}

TEST(SparseSum, DroppedRowsOfTheFirstOperandAreLeftOut) {
  const SparseMatrix a = random_sparse(50, 30, 0.3, 3), b = random_sparse(50, 30, 0.05, 4);
  std::vector<char> dropped(50, 0);
  for (int i = 0; i < 50; i += 3) dropped[i] = 1;
  const SparseMatrix sum = sparse_sum(a, b, &dropped);
  Eigen::MatrixXd expected = Eigen::MatrixXd(a);
  for (int i = 0; i < 50; ++i)
    if (dropped[i]) expected.row(i).setZero();
  expected += Eigen::MatrixXd(b);
  EXPECT_EQ(Eigen::MatrixXd(sum), expected);
  // b's entries in dropped rows stay: only a's are dropped.
  int kept_from_b = 0;
  for (int col = 0; col < b.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(b, col); it; ++it) kept_from_b += dropped[it.row()];
  int in_dropped_rows = 0;
  for (int col = 0; col < sum.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(sum, col); it; ++it) in_dropped_rows += dropped[it.row()];
  EXPECT_EQ(in_dropped_rows, kept_from_b);
}

TEST(SparseSum, EmptyOperands) {
  const SparseMatrix a = random_sparse(20, 10, 0.3, 5);
  SparseMatrix empty(20, 10);
  empty.makeCompressed();
  EXPECT_EQ(Eigen::MatrixXd(sparse_sum(a, empty)), Eigen::MatrixXd(a));
  EXPECT_EQ(Eigen::MatrixXd(sparse_sum(empty, a)), Eigen::MatrixXd(a));
  EXPECT_EQ(sparse_sum(empty, empty).nonZeros(), 0);
}

}  // namespace
}  // namespace fosls
