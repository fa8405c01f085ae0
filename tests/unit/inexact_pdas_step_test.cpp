// pdas with multilevel cycles as its inner solve (solvers/inexact_pdas_step.hpp, docs/method.md
// §8.4): its Newton steps hold the active DOFs exactly at their bounds through the cycles, and
// it reaches exact pdas's solution of a contact box QP and of a Coulomb problem.
#include "solvers/inexact_pdas_step.hpp"

#include <gtest/gtest.h>

#include "../case_discretization.hpp"
#include "../shipped_example.hpp"
#include "../solver/contact_problems.hpp"
#include "case/format/case_reader.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

/// The Signorini square, three levels: a contact zone that is part of the bottom edge.
Discretization<2> signorini() {
  return Discretization<2>(build_mesh_hierarchy(make_square({.size = 0.25}), 2),
                           testing::signorini_square(1.0));
}

Vector solve_by(const Discretization<2>& disc, int newton_cycles, SolverReport& report) {
  SolverOptions options;
  options.method = SolverMethod::kPdas;
  options.newton_cycles = newton_cycles;
  options.tolerance = 1e-11;
  options.max_iterations = 100;
  Vector x;
  report = solve_box_qp(disc.problem().qp, disc.build_level_hierarchy(), options, {}, x);
  return x;
}

TEST(InexactPdasStep, ActiveDofsStayAtTheirBoundsAndResidualIsKept) {
  const Discretization<2> disc = signorini();
  const BoxQp& qp = disc.problem().qp;
  const LevelHierarchy h = disc.build_level_hierarchy();
  InexactPdasStep step(qp, h, MultilevelOptions{}, nullptr, 1);
  PdasActiveSet twin(qp);  // the same test on the same iterates: the step's active sets
  Vector x = Vector::Zero(qp.size()), r = qp.b;
  int held_total = 0;
  for (int k = 0; k < 6; ++k) {
    const std::vector<char> active = twin.next(x, r);
    step.iterate(x, r);
    for (int i = 0; i < qp.size(); ++i)
      if (active[i]) {
        EXPECT_EQ(x[i], twin.bound(active[i], i)) << "iteration " << k << ", DOF " << i;
        ++held_total;
      }
    Vector ax;
    symmetric_multiply(qp.A, x, ax);
    EXPECT_LE((qp.b - ax - r).norm(), 1e-10 * qp.b.norm()) << "iteration " << k;
  }
  EXPECT_GT(held_total, 0);  // the test is about held DOFs
}

TEST(InexactPdasStep, ReachesExactPdasSolutionOfAContactProblem) {
  const Discretization<2> disc = signorini();
  SolverReport exact_report;
  const Vector exact = solve_by(disc, 0, exact_report);
  ASSERT_TRUE(exact_report.converged) << exact_report.message;
  for (const int cycles : {1, 2, 3}) {
    SolverReport report;
    const Vector x = solve_by(disc, cycles, report);
    EXPECT_TRUE(report.converged) << cycles << " cycles: " << report.message;
    EXPECT_LE((x - exact).norm(), 1e-8 * exact.norm()) << cycles << " cycles";
    EXPECT_GT(report.iterations, exact_report.iterations) << "cycles leave each step inexact";
  }
}

/// The incompressible half disk pressed by 0.01 and shifted by 0.004, 𝔣 = 0.3, solved by pdas
/// with `newton_cycles` from the start.
Vector coulomb_by_pdas(int newton_cycles, SolverReport& report) {
  nlohmann::json j = testing::load_shipped_example("hertz_incompressible");
  j["mesh"]["refinements"] = 2;
  j["boundary"]["top"]["displacement"] = {0.004, -0.01};
  j["boundary"]["contact"]["friction"] = {{"coefficient", 0.3}};
  CaseSpec spec = *read_case(j).spec;
  SolverOptions options = spec.solver;
  options.method = SolverMethod::kPdas;
  options.newton_cycles = newton_cycles;
  const std::unique_ptr<Discretization<2>> disc = testing::case_discretization(spec);
  AssembledProblem& problem = disc->mutable_problem();
  KinkedProblem kinked;
  kinked.kinks = &problem.kinks;
  kinked.coulomb = &problem.friction;
  Vector x;
  report = solve_kinked_qp(problem.qp, kinked, disc->build_level_hierarchy(), options, {}, x);
  return x;
}

TEST(InexactPdasStep, ReachesExactPdasSolutionOfACoulombProblem) {
  SolverReport exact_report, report;
  const Vector exact = coulomb_by_pdas(0, exact_report);
  ASSERT_TRUE(exact_report.converged) << exact_report.message;
  const Vector x = coulomb_by_pdas(2, report);
  ASSERT_TRUE(report.converged) << report.message;
  // The same discrete Coulomb problem: the same solution to the solves' tolerance.
  EXPECT_LE((x - exact).norm(), 1e-6 * exact.norm());
}

}  // namespace
}  // namespace fosls
