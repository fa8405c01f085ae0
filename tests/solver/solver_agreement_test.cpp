// Every method reaches the same discrete solution: mmg, tnnmg and pgs
// agree with pdas to a relative energy-norm difference ≤ 1e-8 at tolerance 1e-12, on the
// curved-gap square and on hertz, for λ = 1 and λ = ∞, on uniform and on adapted meshes, and in
// 3D on the Signorini block.
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>

#include "../tet_problems.hpp"
#include "adapted_hierarchy.hpp"
#include "case/format/solver_methods.hpp"
#include "contact_problems.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Solved {
  Vector x;
  SolverReport report;
};

template <int dim>
Solved run(const Discretization<dim>& disc, const LevelHierarchy& h, SolverMethod m, int max_it) {
  SolverOptions o;
  o.method = m;
  o.tolerance = 1e-12;
  o.max_iterations = max_it;
  Solved s;
  s.report = solve_box_qp(disc.problem().qp, h, o, {}, s.x);
  std::printf("%-6s iterations=%5d converged=%d rate=%.3f active=%d\n", method_info(m).name,
              s.report.iterations, s.report.converged, s.report.asymptotic_rate, s.report.active);
  return s;
}

/// ‖a − b‖_A / ‖b‖_A.
double energy_distance(const BoxQp& qp, const Vector& a, const Vector& b) {
  Vector d = a - b, ad, ab;
  symmetric_multiply(qp.A, d, ad);
  symmetric_multiply(qp.A, b, ab);
  return std::sqrt(d.dot(ad) / b.dot(ab));
}

template <int dim>
void check_agreement(const Discretization<dim>& disc, std::vector<SolverMethod> methods) {
  const LevelHierarchy h = disc.build_level_hierarchy();
  const auto& qp = disc.problem().qp;
  const Solved ref = run(disc, h, SolverMethod::kPdas, 50);
  ASSERT_TRUE(ref.report.converged);
  ASSERT_GT(ref.report.active, 0);
  for (SolverMethod m : methods) {
    const Solved s = run(disc, h, m, m == SolverMethod::kPgs ? 100000 : 300);
    EXPECT_TRUE(s.report.converged) << method_info(m).name;
    EXPECT_LE(energy_distance(qp, s.x, ref.x), 1e-8) << method_info(m).name;
    EXPECT_TRUE(qp.feasible(s.x)) << method_info(m).name;
    EXPECT_EQ(s.report.active, ref.report.active) << method_info(m).name;
  }
}

Discretization<2> square(double lambda, int refinements) {
  return Discretization<2>(build_mesh_hierarchy(make_square({.size = 0.25}), refinements),
                           testing::signorini_square(lambda));
}
Discretization<2> hertz(double lambda, int refinements) {
  return Discretization<2>(build_mesh_hierarchy(make_hertz({.size = 0.1}), refinements),
                           testing::hertz(lambda));
}

/// `refinements` uniform levels, then four adaptive bisection steps.
Discretization<2> adapted(const ProblemData<2>& data, Mesh coarse, int refinements) {
  return Discretization<2>(
      testing::adapted_hierarchy(build_mesh_hierarchy(std::move(coarse), refinements), data, 4),
      data);
}

// The multilevel methods on 3 levels; single-level PGS, whose rate tends to 1 as h → 0
// (≈ 0.999 here), on 2 levels so that 1e-12 is reached in a test's time.
const std::vector<SolverMethod> kMultilevel = {SolverMethod::kMmg, SolverMethod::kTnnmg};
const std::vector<SolverMethod> kSingleLevel = {SolverMethod::kPgs};

TEST(Agreement, CurvedGapSquareLambdaOne) {
  check_agreement(square(1.0, 2), kMultilevel);
  check_agreement(square(1.0, 1), kSingleLevel);
}
TEST(Agreement, CurvedGapSquareIncompressible) {
  check_agreement(square(kInf, 2), kMultilevel);
  check_agreement(square(kInf, 1), kSingleLevel);
}
TEST(Agreement, HertzLambdaOne) {
  check_agreement(hertz(1.0, 2), kMultilevel);
  check_agreement(hertz(1.0, 1), kSingleLevel);
}
TEST(Agreement, HertzIncompressible) {
  check_agreement(hertz(kInf, 2), kMultilevel);
  check_agreement(hertz(kInf, 1), kSingleLevel);
}
TEST(Agreement, AdaptedCurvedGapSquare) {
  const ProblemData<2> data = testing::signorini_square(1.0);
  check_agreement(adapted(data, make_square({.size = 0.25}), 1), kMultilevel);
  check_agreement(adapted(data, make_square({.size = 0.25}), 0), kSingleLevel);
}
TEST(Agreement, AdaptedHertz) {
  for (double lambda : {1.0, kInf}) {
    const ProblemData<2> data = testing::hertz(lambda);
    check_agreement(adapted(data, make_hertz({.size = 0.1}), 1), kMultilevel);
  }
  check_agreement(adapted(testing::hertz(1.0), make_hertz({.size = 0.1}), 0), kSingleLevel);
}
TEST(Agreement, SignoriniBlockIn3d) {
  for (double lambda : {1.0, kInf}) {
    const ProblemData<3> data = testing::signorini_block(lambda);
    check_agreement(Discretization<3>(build_tet_hierarchy(make_box({2, 2, 2}), 2), data),
                    kMultilevel);
    check_agreement(Discretization<3>(build_tet_hierarchy(make_box({2, 2, 2}), 0), data),
                    kSingleLevel);
  }
}

}  // namespace
}  // namespace fosls
