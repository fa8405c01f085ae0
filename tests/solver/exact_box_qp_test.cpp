// The exact bound-constrained QP solvers (solve_dense_box_qp, SparseBoxQpSolver) against a
// brute-force enumeration of active sets on small random SPD problems:
//   minimise ½ δᵀAδ − rᵀδ  subject to  lo ≤ δ ≤ hi,  lo ≤ 0 ≤ hi.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "box_qp_enumeration.hpp"
#include "core/indefinite_system.hpp"
#include "solvers/exact_box_qp.hpp"

namespace fosls {
namespace {

using testing::RandomBoxQp;

TEST(DenseBoxQp, MatchesEnumerationOfActiveSets) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const RandomBoxQp p = testing::random_box_qp(rng, 1 + trial % 7);
    Vector delta;
    ASSERT_TRUE(solve_dense_box_qp(Eigen::MatrixXd(p.A), p.r, p.lo, p.hi, delta));
    const Vector best = testing::enumerate_box_qp(p.A, p.r, p.lo, p.hi);
    EXPECT_LE((delta - best).norm(), 1e-10 * (1.0 + best.norm())) << "trial " << trial;
    EXPECT_TRUE(testing::within(delta, p.lo, p.hi)) << "trial " << trial;
  }
}

// Both ways of solving the free sets (solvers/free_set_solver.hpp); held rows also start the
// primal–dual steps from the last settled active set.
class SparseBoxQp : public ::testing::TestWithParam<BlockFactorization> {};

TEST_P(SparseBoxQp, MatchesEnumerationOfActiveSets) {
  // Here every solve ends by primal–dual steps whose active sets settled; the fallback to the
  // primal method is checked by the next test.
  std::mt19937 rng(11);
  int by_primal_dual = 0, by_primal = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const RandomBoxQp p = testing::random_box_qp(rng, 1 + trial % 7);
    SparseBoxQpSolver solver(p.A, GetParam());
    Vector delta;
    EXPECT_TRUE(solver.solve(p.r, p.lo, p.hi, delta));
    (solver.solved_primal_dual() == 1 ? by_primal_dual : by_primal) += 1;
    const Vector best = testing::enumerate_box_qp(p.A, p.r, p.lo, p.hi);
    EXPECT_LE((delta - best).norm(), 1e-10 * (1.0 + best.norm())) << "trial " << trial;
    EXPECT_TRUE(testing::within(delta, p.lo, p.hi)) << "trial " << trial;
  }
  std::printf("ended by primal-dual steps: %d, by the primal method: %d\n", by_primal_dual,
              by_primal);
  EXPECT_GT(by_primal_dual, 150);
}

TEST_P(SparseBoxQp, FallsBackToThePrimalMethodWhenPrimalDualStepsCycle) {
  // An SPD matrix on which the primal–dual active sets cycle (found by a search over random
  // 3 × 3 problems): the solve must still end at the exact minimiser, by the primal method.
  Eigen::MatrixXd a(3, 3);
  a << 2.4604636436779996, -2.997937478987005, -2.695403457194911,  //
      -2.997937478987005, 3.8632606740264768, 3.2181822276326146,   //
      -2.695403457194911, 3.2181822276326146, 3.3429986653379595;
  const SparseMatrix sparse = a.sparseView();
  Vector r(3), lo(3), hi(3);
  r << -0.14216403090123211, -0.8310339591200061, 0.49867660991367335;
  lo << -0.95977563233322127, -0.5304480608255786, -0.92528623665586618;
  hi << 0.077530391687385222, 0.39716859109242436, 0.071391235607463827;
  SparseBoxQpSolver solver(sparse, GetParam());
  Vector delta;
  EXPECT_TRUE(solver.solve(r, lo, hi, delta));
  EXPECT_EQ(solver.solved_primal_dual(), 0);
  EXPECT_EQ(solver.primal_dual_steps(), 20);  // the cap
  const Vector best = testing::enumerate_box_qp(sparse, r, lo, hi);
  EXPECT_LE((delta - best).norm(), 1e-10 * (1.0 + best.norm()));
  EXPECT_TRUE(testing::within(delta, lo, hi));
}

TEST_P(SparseBoxQp, ReusesItsFactorisationAcrossCallsWithoutChangingTheAnswer) {
  // The solver keeps the factorisation of the last free set (and, with held rows, starts from the
  // last settled active set): solving several right-hand sides in a row, in both orders, must
  // give what a fresh solver gives, and the exact minimiser.
  std::mt19937 rng(3);
  const RandomBoxQp p = testing::random_box_qp(rng, 7);
  std::vector<Vector> rhs;
  for (int k = 0; k < 6; ++k) rhs.push_back(testing::random_box_qp(rng, 7).r);
  SparseBoxQpSolver reused(p.A, GetParam());
  for (int pass = 0; pass < 2; ++pass)
    for (int k = 0; k < 6; ++k) {
      const Vector& r = rhs[pass == 0 ? k : 5 - k];
      Vector a, b;
      reused.solve(r, p.lo, p.hi, a);
      SparseBoxQpSolver(p.A, GetParam()).solve(r, p.lo, p.hi, b);
      EXPECT_LE((a - b).norm(), 1e-12 * (1.0 + b.norm()));
      const Vector best = testing::enumerate_box_qp(p.A, r, p.lo, p.hi);
      EXPECT_LE((a - best).norm(), 1e-10 * (1.0 + best.norm()));
    }
}

TEST(SparseBoxQpHeldRows, StartsFromTheLastSettledActiveSet) {
  // Solving the same problem again: the settled active set of the first solve is the answer's,
  // so the second takes one primal–dual step (with the factor it already has).
  std::mt19937 rng(5);
  int repeated = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const RandomBoxQp p = testing::random_box_qp(rng, 2 + trial % 6);
    SparseBoxQpSolver solver(p.A, BlockFactorization::held_rows);
    Vector first, second;
    solver.solve(p.r, p.lo, p.hi, first);
    if (solver.solved_primal_dual() != 1) continue;
    const int steps = solver.primal_dual_steps();
    solver.solve(p.r, p.lo, p.hi, second);
    EXPECT_EQ(solver.primal_dual_steps(), steps + 1) << "trial " << trial;
    EXPECT_LE((first - second).norm(), 1e-12 * (1.0 + first.norm())) << "trial " << trial;
    ++repeated;
  }
  EXPECT_GT(repeated, 40);
}

TEST_P(SparseBoxQp, RefactorsNewValuesOfTheSamePatternAsAFreshSolverWould) {
  // The coarsest level of a 3D cycle is refactored, not rebuilt, when the truncation changes its
  // values (held rows): the answer must be a fresh solver's and the exact minimiser, also after
  // a warm start from the old matrix's settled active set. Reduced solvers keep nothing and
  // refuse, as does a held-rows solver offered another pattern.
  std::mt19937 rng(13);
  for (int trial = 0; trial < 40; ++trial) {
    const RandomBoxQp p = testing::random_box_qp(rng, 3 + trial % 5);
    const int n = static_cast<int>(p.r.size());
    SparseMatrix identity(n, n);
    identity.setIdentity();
    SparseMatrix changed = 0.5 * p.A + 0.3 * identity;
    changed.makeCompressed();
    const Vector r2 = testing::random_box_qp(rng, n).r;
    SparseBoxQpSolver solver(p.A, GetParam());
    Vector first, refactored, fresh;
    solver.solve(p.r, p.lo, p.hi, first);
    const bool kept = solver.refactor(changed);
    EXPECT_EQ(kept, GetParam() == BlockFactorization::held_rows) << "trial " << trial;
    if (!kept) continue;
    solver.solve(r2, p.lo, p.hi, refactored);
    SparseBoxQpSolver(changed, GetParam()).solve(r2, p.lo, p.hi, fresh);
    EXPECT_LE((refactored - fresh).norm(), 1e-12 * (1.0 + fresh.norm())) << "trial " << trial;
    const Vector best = testing::enumerate_box_qp(changed, r2, p.lo, p.hi);
    EXPECT_LE((refactored - best).norm(), 1e-10 * (1.0 + best.norm())) << "trial " << trial;
    EXPECT_TRUE(testing::within(refactored, p.lo, p.hi)) << "trial " << trial;
    EXPECT_FALSE(solver.refactor(identity)) << "trial " << trial;  // another pattern
  }
}

TEST(SparseBoxQpHeldRows, RefactoringAnIndefiniteMatrixIsReported) {
  Eigen::MatrixXd a(2, 2);
  a << 2.0, 1.0, 1.0, 2.0;
  SparseMatrix definite = a.sparseView();
  SparseBoxQpSolver solver(definite, BlockFactorization::held_rows);
  a << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and −1, the same pattern
  SparseMatrix indefinite = a.sparseView();
  EXPECT_THROW(solver.refactor(indefinite), IndefiniteSystemError);
}

INSTANTIATE_TEST_SUITE_P(Factorizations, SparseBoxQp,
                         ::testing::Values(BlockFactorization::reduced,
                                           BlockFactorization::held_rows),
                         [](const auto& info) {
                           return info.param == BlockFactorization::reduced ? "reduced"
                                                                            : "held_rows";
                         });

TEST(DenseBoxQp, ReportsAnIndefiniteMatrix) {
  Eigen::MatrixXd a(2, 2);
  a << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and −1
  const Vector r = Vector::Ones(2), lo = Vector::Constant(2, -kNoBound),
               hi = Vector::Constant(2, kNoBound);
  Vector delta;
  EXPECT_FALSE(solve_dense_box_qp(a, r, lo, hi, delta));
}

}  // namespace
}  // namespace fosls
