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

// Under bisection a coarse U_n whose fine U_n are all truncated keeps only its leakage into the
// fine tangential components (the sine of the angle between the levels' normals, 10⁻⁵ in the
// adapted quarter ball whose ninth step was refused as indefinite): such a column is truncated
// away entirely, applied or formed, while a column that keeps a real part of P's stays.
TEST(TruncatedProlongation, AColumnLeftWithOnlyLeakageIsTruncatedAway) {
  const int n = 6, nc = 3;
  std::vector<Eigen::Triplet<double>> entries = {
      {0, 0, 1.0}, {1, 0, 0.5}, {2, 0, 2e-5},  // column 0: only the leakage is kept
      {3, 1, 1.0}, {4, 1, 0.5}, {2, 1, 0.01},  // column 1: 1 % of P's is kept
      {5, 2, 1.0}, {1, 2, 0.5}};               // column 2: entirely truncated
  SparseMatrix p(n, nc);
  p.setFromTriplets(entries.begin(), entries.end());
  p.makeCompressed();
  const std::vector<char> dropped = {1, 1, 0, 1, 1, 1};
  const SparseMatrix none(n, nc);
  const TruncatedProlongation a = TruncatedProlongation::applied(p, dropped, none);
  const TruncatedProlongation f = TruncatedProlongation::formed(sparse_sum(p, none, &dropped), &p);
  const std::vector<char> expected = {1, 0, 1};
  EXPECT_EQ(a.vanished_columns(), expected);
  EXPECT_EQ(f.vanished_columns(), expected);

  const Vector r = Vector::Constant(n, 1.0);
  Vector rc_a, rc_f;
  a.restrict_to(r, rc_a);
  f.restrict_to(r, rc_f);
  EXPECT_EQ(rc_a[0], 0.0);
  EXPECT_EQ(rc_f[0], 0.0);
  EXPECT_DOUBLE_EQ(rc_a[1], 0.01);
  EXPECT_DOUBLE_EQ(rc_f[1], 0.01);

  Vector v_a, v_f;
  a.prolongate(Vector::Unit(nc, 0), v_a);
  f.prolongate(Vector::Unit(nc, 0), v_f);
  EXPECT_TRUE(v_a.isZero(0.0));
  EXPECT_TRUE(v_f.isZero(0.0));
  // Without truncation nothing is negligible: P itself.
  const TruncatedProlongation whole = TruncatedProlongation::applied(p, {}, none);
  EXPECT_EQ(whole.vanished_columns(), std::vector<char>(nc, 0));
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
