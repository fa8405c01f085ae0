// TruncatedProlongation: P̃ applied from P, the truncated rows and the flux moves acts exactly
// as the formed matrix P̃ = P without those rows + moves (the finest level's form).
#include "solvers/truncated_prolongation.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "random_sparse.hpp"
#include "solvers/sparse_sum.hpp"

namespace fosls {
namespace {

using testing::random_sparse;

TEST(TruncatedProlongation, AppliedActsAsTheFormedMatrix) {
  const int n = 80, nc = 25;
  const SparseMatrix p = random_sparse(n, nc, 0.1, 1);
  SparseMatrix moves = random_sparse(n, nc, 0.01, 2);
  std::vector<char> dropped(n, 0);
  for (int i = 0; i < n; i += 3) dropped[i] = 1;
  // A column all of whose entries are in dropped rows and that no move reaches: it vanishes.
  SparseMatrix q = p;
  for (int i = 0; i < n; ++i) q.coeffRef(i, 7) = dropped[i] ? 1.0 : 0.0;
  q.prune(0.0);
  q.makeCompressed();
  moves.prune([](int, int col, double) { return col != 7; });
  const SparseMatrix formed = sparse_sum(q, moves, &dropped);
  const TruncatedProlongation a = TruncatedProlongation::applied(q, dropped, moves);
  const TruncatedProlongation f = TruncatedProlongation::formed(formed);
  ASSERT_EQ(a.matrix(), nullptr);
  ASSERT_NE(f.matrix(), nullptr);

  const Vector r = Vector::LinSpaced(n, -1.0, 3.0);
  Vector rc_a, rc_f;
  a.restrict_to(r, rc_a);
  f.restrict_to(r, rc_f);
  EXPECT_LT((rc_a - rc_f).norm(), 1e-13 * rc_f.norm());
  EXPECT_LT((rc_a - Vector(formed.transpose() * r)).norm(), 1e-13 * rc_f.norm());

  const Vector c = Vector::LinSpaced(nc, 2.0, -1.0);
  Vector v_a, v_f;
  a.prolongate(c, v_a);
  f.prolongate(c, v_f);
  EXPECT_LT((v_a - v_f).norm(), 1e-13 * v_f.norm());
  const Eigen::MatrixXd dense_moves(moves);
  for (int i = 0; i < n; ++i)
    if (dropped[i] && dense_moves.row(i).isZero(0.0)) EXPECT_EQ(v_a[i], 0.0) << i;

  const std::vector<char> vanished = a.vanished_columns();
  EXPECT_EQ(vanished, f.vanished_columns());
  EXPECT_TRUE(vanished[7]);
  EXPECT_EQ(std::count(vanished.begin(), vanished.end(), 1), 1);
}

TEST(TruncatedProlongation, WithoutTruncationItIsP) {
  const SparseMatrix p = random_sparse(40, 12, 0.2, 3);
  const TruncatedProlongation a =
      TruncatedProlongation::applied(p, {}, SparseMatrix(p.rows(), p.cols()));
  const Vector c = Vector::LinSpaced(12, 1.0, 2.0);
  Vector v;
  a.prolongate(c, v);
  EXPECT_LT((v - Vector(p * c)).norm(), 1e-14 * v.norm());
}

}  // namespace
}  // namespace fosls
