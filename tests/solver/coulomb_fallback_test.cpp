// Coulomb's fallback (solvers/coulomb_fallback.hpp, docs/method.md §8.4): when mmg counts as
// stalled, and that pdas, continuing from mmg's iterate, finishes the same discrete problem as a
// pdas solve from the start, with one report and one numbering of the iterations.
#include "solvers/coulomb_fallback.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "../case_discretization.hpp"
#include "../shipped_example.hpp"
#include "assembly/discretization.hpp"
#include "case/format/case_reader.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

std::vector<IterationRecord> history_of(const std::vector<double>& residuals) {
  std::vector<IterationRecord> h;
  for (std::size_t k = 0; k < residuals.size(); ++k) {
    IterationRecord rec;
    rec.iteration = static_cast<int>(k);
    rec.kkt_residual = residuals[k];
    h.push_back(rec);
  }
  return h;
}

TEST(StallTest, BestResidualOfTheWindowAgainstTheBestBefore) {
  const StallTest test{4, 3, 0.5};  // stalled when the window's best is above 0.125 × before
  // Too early: fewer than `earliest` iterations.
  EXPECT_FALSE(test.stalled(history_of({1, 1, 1, 1})));
  // Falling by 0.4 per iteration: not stalled.
  EXPECT_FALSE(test.stalled(history_of({1, 0.4, 0.16, 0.064, 0.0256})));
  // The window {0.9, 0.2, 0.15} against the best before it, 1: 0.15 > 0.125, stalled.
  EXPECT_TRUE(test.stalled(history_of({1, 2, 0.9, 0.2, 0.15})));
  // A jump (an update) inside the window does not count; its best, 0.1, is below 0.125.
  EXPECT_FALSE(test.stalled(history_of({1, 2, 30, 0.1, 5})));
  EXPECT_FALSE(StallTest::never().stalled(history_of(std::vector<double>(50, 1.0))));
}

/// The incompressible half disk pressed by 0.01 and shifted by 0.004, 𝔣 = 0.3.
std::unique_ptr<Discretization<2>> coulomb_hertz(SolverOptions& options) {
  nlohmann::json j = testing::load_shipped_example("hertz_incompressible");
  j["mesh"]["refinements"] = 2;
  j["boundary"]["top"]["displacement"] = {0.004, -0.01};
  j["boundary"]["contact"]["friction"] = {{"coefficient", 0.3}};
  CaseSpec spec = *read_case(j).spec;
  options = spec.solver;
  return testing::case_discretization(spec);
}

struct Solved {
  SolverReport report;
  Vector x;
  std::vector<int> observed;  ///< the iterations the observer saw, in order
};

Solved solve(SolverMethod method, const StallTest& stall, bool fallback) {
  SolverOptions options;
  const std::unique_ptr<Discretization<2>> disc = coulomb_hertz(options);
  options.method = method;
  options.coulomb_fallback = fallback;
  AssembledProblem& problem = disc->mutable_problem();
  KinkedProblem kinked;
  kinked.kinks = &problem.kinks;
  kinked.coulomb = &problem.friction;
  kinked.schedule.stall = stall;
  Solved s;
  SolverObserver observer;
  observer.on_iteration = [&s](const IterationRecord& rec) { s.observed.push_back(rec.iteration); };
  s.report =
      solve_kinked_qp(problem.qp, kinked, disc->build_level_hierarchy(), options, observer, s.x);
  return s;
}

TEST(CoulombFallback, PdasFinishesAStalledMmgSolveAsPdasAloneDoes) {
  // A stall test that always fires at iteration 5.
  const Solved fb = solve(SolverMethod::kMmg, {5, 2, 0.0}, true);
  const Solved pdas = solve(SolverMethod::kPdas, StallTest::never(), true);
  ASSERT_TRUE(fb.report.converged) << fb.report.message;
  ASSERT_TRUE(pdas.report.converged) << pdas.report.message;
  EXPECT_EQ(fb.report.switched_at, 5);
  EXPECT_EQ(pdas.report.switched_at, 0);
  EXPECT_GT(fb.report.iterations, 5);
  ASSERT_EQ(static_cast<int>(fb.report.history.size()), fb.report.iterations + 1);
  for (int k = 0; k <= fb.report.iterations; ++k) {
    EXPECT_EQ(fb.report.history[k].iteration, k);
    EXPECT_EQ(fb.observed[k], k);
  }
  EXPECT_EQ(static_cast<int>(fb.observed.size()), fb.report.iterations + 1);
  // The same discrete Coulomb problem: the same solution to the solves' tolerance.
  EXPECT_LE((fb.x - pdas.x).norm(), 1e-6 * pdas.x.norm());
}

TEST(CoulombFallback, NotWhenSwitchedOffNorWhereMmgDoesNotStall) {
  const Solved off = solve(SolverMethod::kMmg, {5, 2, 0.0}, false);
  EXPECT_TRUE(off.report.converged);
  EXPECT_EQ(off.report.switched_at, 0);
  EXPECT_FALSE(off.report.stalled);
  // The default stall test (a schedule's window 0 asks for it) does not fire on this case.
  const Solved plain = solve(SolverMethod::kMmg, StallTest::never(), true);
  EXPECT_TRUE(plain.report.converged);
  EXPECT_EQ(plain.report.switched_at, 0);
}

}  // namespace
}  // namespace fosls
