// The error estimator and Dörfler marking: the indicators split J exactly, and the marked set
// is the smallest one that covers θ of the total.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "assembly/error_indicators.hpp"
#include "contact_problems.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

double sum_of(const std::vector<double>& v, const std::vector<int>& which) {
  double s = 0.0;
  for (int t : which) s += v[t];
  return s;
}

TEST(ErrorIndicators, SumToTheFunctionalOfTheContactSolution) {
  const Discretization<2> disc(build_mesh_hierarchy(make_hertz({.size = 0.1}), 1),
                               testing::hertz(1.0));
  const BoxQp& qp = disc.problem().qp;
  Vector x;
  SolverOptions options;
  options.method = SolverMethod::kPdas;
  ASSERT_TRUE(solve_box_qp(qp, LevelHierarchy{}, options, {}, x).converged);
  const Vector full = disc.assembler().full_vector(disc.problem(), x);
  const FunctionalParts parts = disc.assembler().functional(full);
  ASSERT_GT(parts.contact, 0.0);  // the contact term's share is part of the split
  const ErrorEstimate e = error_estimate(parts);
  ASSERT_EQ(e.indicators.size(),
            static_cast<std::size_t>(disc.finest_space().mesh().num_triangles()));
  const double j = qp.energy(x);
  EXPECT_NEAR(e.total, j, 1e-10 * j);
  EXPECT_NEAR(e.estimator(), std::sqrt(j), 1e-10 * std::sqrt(j));
  EXPECT_GE(*std::min_element(e.indicators.begin(), e.indicators.end()), 0.0);
}

TEST(DorflerMarking, TakesTheLargestIndicatorsUntilThetaIsCovered) {
  const std::vector<double> eta2 = {1.0, 8.0, 0.5, 4.0, 2.0, 0.0, 0.5};   // total 16
  EXPECT_EQ(dorfler_marking(eta2, 0.5), (std::vector<int>{1}));           // 8 ≥ 8
  EXPECT_EQ(dorfler_marking(eta2, 0.6), (std::vector<int>{1, 3}));        // 12 ≥ 9.6
  EXPECT_EQ(dorfler_marking(eta2, 0.9), (std::vector<int>{1, 3, 4, 0}));  // 15 ≥ 14.4
  // Ties in index order; θ = 1 takes every positive indicator and no zero one.
  EXPECT_EQ(dorfler_marking(eta2, 1.0), (std::vector<int>{1, 3, 4, 0, 2, 6}));
  EXPECT_TRUE(dorfler_marking(std::vector<double>(5, 0.0), 0.5).empty());
  EXPECT_THROW(dorfler_marking(eta2, 0.0), std::invalid_argument);
  EXPECT_THROW(dorfler_marking(eta2, 1.5), std::invalid_argument);
}

TEST(DorflerMarking, TheMarkedSetIsMinimalOnRealIndicators) {
  // Indicators of a solved Signorini square: many distinct values, a few large ones.
  const Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.25}), 2),
                               testing::signorini_square(1.0));
  Vector x;
  SolverOptions options;
  options.method = SolverMethod::kPdas;
  ASSERT_TRUE(solve_box_qp(disc.problem().qp, LevelHierarchy{}, options, {}, x).converged);
  const ErrorEstimate e =
      error_estimate(disc.assembler().functional(disc.assembler().full_vector(disc.problem(), x)));
  for (double theta : {0.3, 0.5, 0.8}) {
    const std::vector<int> marked = dorfler_marking(e.indicators, theta);
    ASSERT_FALSE(marked.empty());
    EXPECT_LT(marked.size(), e.indicators.size());
    EXPECT_GE(sum_of(e.indicators, marked), theta * e.total) << theta;
    // Minimal: without its smallest member the set falls short, and no triangle left out has
    // a larger indicator than one taken.
    std::vector<int> fewer(marked.begin(), marked.end() - 1);
    EXPECT_LT(sum_of(e.indicators, fewer), theta * e.total) << theta;
    double smallest_taken = e.indicators[marked.back()];
    std::vector<char> taken(e.indicators.size(), 0);
    for (int t : marked) taken[t] = 1;
    for (std::size_t t = 0; t < taken.size(); ++t) {
      if (!taken[t]) {
        EXPECT_LE(e.indicators[t], smallest_taken);
      }
    }
  }
}

}  // namespace
}  // namespace fosls
