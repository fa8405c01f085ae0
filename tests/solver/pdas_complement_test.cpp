// pdas's solve through the bounded DOFs' Schur complement (solvers/bounded_complement_solver.hpp)
// against a fresh factorisation of the held-rows matrix: the same solution to round-off over a
// sequence of held sets, and pdas's iteration count, solution, active set and force, in 2D
// and 3D.
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <limits>
#include <random>

#include "../tet_problems.hpp"
#include "contact_problems.hpp"
#include "solvers/bounded_complement_solver.hpp"
#include "solvers/pdas_step.hpp"

namespace fosls {
namespace {

std::vector<int> bounded_dofs(const BoxQp& qp) {
  std::vector<int> bounded;
  for (int i = 0; i < qp.size(); ++i)
    if (is_bounded_above(qp.upper[i]) || is_bounded_below(qp.lower[i])) bounded.push_back(i);
  return bounded;
}

/// x with x_H = psi_H and A x = b on the other rows, by a factorisation of A with the held
/// rows and columns replaced by the identity's (pdas's form before the complement).
Vector solve_held_rows(const SparseMatrix& a, const std::vector<char>& held, const Vector& b,
                       const Vector& psi) {
  SparseMatrix m = a;
  for (int col = 0; col < m.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(m, col); it; ++it)
      if (held[it.row()] || held[col]) it.valueRef() = it.row() == col ? 1.0 : 0.0;
  Vector psi_held = Vector::Zero(b.size());
  for (int i = 0; i < b.size(); ++i)
    if (held[i]) psi_held[i] = psi[i];
  Vector rhs = b - a * psi_held;
  for (int i = 0; i < b.size(); ++i)
    if (held[i]) rhs[i] = psi[i];
  Eigen::CholmodSupernodalLLT<SparseMatrix> llt(m);
  EXPECT_EQ(llt.info(), Eigen::Success);
  return llt.solve(rhs);
}

/// Held sets drawn from the bounded DOFs, each differing from the last in a few DOFs (as pdas's
/// active sets do), with random held values: the complement's solution equals the fresh one.
void expect_complement_matches_factorisation(const BoxQp& qp) {
  const std::vector<int> bounded = bounded_dofs(qp);
  ASSERT_GE(bounded.size(), 8u);
  const auto solver = BoundedComplementSolver::make(qp.A, bounded, 0.0);
  ASSERT_NE(solver, nullptr);
  std::mt19937 rng(7);
  std::uniform_int_distribution<size_t> pick(0, bounded.size() - 1);
  std::uniform_real_distribution<double> value(-0.01, 0.01);
  std::vector<char> held(qp.size(), 0);
  Vector psi = Vector::Zero(qp.size());
  for (const int i : bounded) psi[i] = value(rng);
  for (int round = 0; round < 12; ++round) {
    const int flips = round == 0 ? static_cast<int>(bounded.size() / 2) : 1 + round % 4;
    for (int f = 0; f < flips; ++f) {
      const int i = bounded[pick(rng)];
      held[i] = !held[i];
    }
    Vector x;
    ASSERT_TRUE(solver->solve(held, qp.b, psi, x));
    const Vector fresh = solve_held_rows(qp.A, held, qp.b, psi);
    EXPECT_LE((x - fresh).norm(), 1e-10 * fresh.norm()) << "round " << round;
    for (int i = 0; i < qp.size(); ++i)
      if (held[i]) {
        EXPECT_EQ(x[i], psi[i]);
      }
  }
}

struct PdasRun {
  int iterations = 0;
  Vector x, r;
};

/// pdas from the projected zero until the iterate repeats (its active set no longer changes).
PdasRun run_pdas(const BoxQp& qp, double complement_min_flops) {
  PdasStep step(qp, complement_min_flops);
  PdasRun run;
  run.x = Vector::Zero(qp.size()).cwiseMax(qp.lower).cwiseMin(qp.upper);
  run.r = qp.b - qp.A * run.x;
  for (int k = 0; k < 40; ++k) {
    const Vector previous = run.x;
    step.iterate(run.x, run.r);
    ++run.iterations;
    if ((run.x - previous).norm() <= 1e-12 * run.x.norm()) break;
  }
  return run;
}

/// The same iterations, solution, active set and force (the multipliers' sum over the active
/// DOFs) with the complement as with a factorisation per active set.
void expect_same_pdas(const BoxQp& qp) {
  const PdasRun with = run_pdas(qp, 0.0);
  const PdasRun without = run_pdas(qp, std::numeric_limits<double>::infinity());
  EXPECT_EQ(with.iterations, without.iterations);
  EXPECT_GE(with.iterations, 3);  // the active set changed at least once
  EXPECT_LT(with.iterations, 40);
  // Not iterate by iterate: on the block some DOFs of the first iterates land on their bound in
  // the free solve, and round-off decides their next state (the two runs part at iteration 1
  // on 2–3 such DOFs and meet again at the solution).
  EXPECT_LE((with.x - without.x).norm(), 1e-10 * without.x.norm());
  EXPECT_EQ(qp.active_set(with.x), qp.active_set(without.x));
  double force_with = 0.0, force_without = 0.0;
  int active = 0;
  const std::vector<char> at_bound = qp.active_set(without.x);
  for (int i = 0; i < qp.size(); ++i)
    if (at_bound[i]) {
      force_with += with.r[i];
      force_without += without.r[i];
      ++active;
    }
  EXPECT_GT(active, 0);
  EXPECT_NEAR(force_with, force_without, 1e-10 * std::abs(force_without));
}

TEST(PdasComplement, MatchesAFreshFactorisationIn2d) {
  const Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.25}), 3),
                               testing::signorini_square(1.0));
  expect_complement_matches_factorisation(disc.problem().qp);
}

TEST(PdasComplement, MatchesAFreshFactorisationIn3d) {
  const Discretization<3> disc(build_tet_hierarchy(make_box({2, 2, 2}), 2),
                               testing::signorini_block(1.0));
  expect_complement_matches_factorisation(disc.problem().qp);
}

TEST(PdasComplement, SameIterationsActiveSetAndForceIn2d) {
  const Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.25}), 3),
                               testing::signorini_square(1.0));
  expect_same_pdas(disc.problem().qp);
}

TEST(PdasComplement, SameIterationsActiveSetAndForceIn3d) {
  const Discretization<3> disc(build_tet_hierarchy(make_box({2, 2, 2}), 2),
                               testing::signorini_block(1.0));
  expect_same_pdas(disc.problem().qp);
}

}  // namespace
}  // namespace fosls
