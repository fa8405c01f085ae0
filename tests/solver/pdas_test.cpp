// The primal–dual active-set method (method pdas of solve_box_qp) against the brute-force
// enumeration of active sets: on a small assembled contact problem, whose bounded DOFs are few
// enough to enumerate, and on small random problems with an M-matrix (where the method is
// known to converge).
#include <gtest/gtest.h>

#include <random>

#include "box_qp_enumeration.hpp"
#include "contact_problems.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

Vector solve_by_pdas(const BoxQp& qp, SolverReport& report) {
  SolverOptions options;
  options.method = SolverMethod::kPdas;
  options.tolerance = 1e-13;
  options.max_iterations = 50;
  Vector x;
  report = solve_box_qp(qp, LevelHierarchy{}, options, {}, x);
  return x;
}

TEST(Pdas, MatchesEnumerationOnAnAssembledContactProblem) {
  for (const bool curved_gap : {true, false}) {
    const ProblemData<2> data =
        curved_gap ? testing::signorini_square(1.0) : testing::flat_square(1.0);
    const Discretization disc(build_mesh_hierarchy(make_square({.size = 0.25}), 0), data);
    const BoxQp& qp = disc.problem().qp;
    int bounded = 0;
    for (int i = 0; i < qp.size(); ++i) bounded += is_bounded_above(qp.upper[i]);
    ASSERT_GE(bounded, 6);
    ASSERT_LE(bounded, 16);  // 2^16 dense solves at most
    SolverReport report;
    const Vector x = solve_by_pdas(qp, report);
    EXPECT_TRUE(report.converged) << report.message;
    const Vector best = testing::enumerate_box_qp(qp.A, qp.b, qp.lower, qp.upper);
    ASSERT_EQ(best.size(), qp.size());
    EXPECT_LE((x - best).norm(), 1e-9 * best.norm()) << (curved_gap ? "curved gap" : "flat");
    // Some bounds are active and some are not: the test is about choosing the active set.
    int active = 0;
    for (int i = 0; i < qp.size(); ++i) active += is_at_bound(best[i], qp.lower[i], qp.upper[i]);
    EXPECT_GT(active, 0);
    EXPECT_LT(active, bounded);
  }
}

TEST(Pdas, MatchesEnumerationOnRandomMMatrixProblems) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 2 + trial % 8;
    // M-matrix: non-positive couplings, strictly diagonally dominant.
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (u(rng) < 0.6) a(i, j) = a(j, i) = -u(rng);
    for (int i = 0; i < n; ++i) a(i, i) = -a.row(i).sum() + 0.1 + u(rng);
    BoxQp qp;
    qp.A = a.sparseView();
    qp.b.resize(n), qp.lower.resize(n), qp.upper.resize(n);
    for (int i = 0; i < n; ++i) {
      qp.b[i] = 2.0 * u(rng) - 0.5;
      qp.lower[i] = -kNoBound;  // pdas handles upper bounds, as the contact problem has
      qp.upper[i] = u(rng) < 0.7 ? 0.5 * u(rng) - 0.1 : kNoBound;
    }
    SolverReport report;
    const Vector x = solve_by_pdas(qp, report);
    EXPECT_TRUE(report.converged) << "trial " << trial << ": " << report.message;
    const Vector best = testing::enumerate_box_qp(qp.A, qp.b, qp.lower, qp.upper);
    EXPECT_LE((x - best).norm(), 1e-10 * (1.0 + best.norm())) << "trial " << trial;
  }
}

}  // namespace
}  // namespace fosls
