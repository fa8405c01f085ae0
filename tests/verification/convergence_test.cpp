// Convergence of the FOSLS discretisation for a smooth manufactured solution: the fitted
// orders of the H1 and H(div) errors and of the functional.
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <cstdio>

#include "verification_problems.hpp"

namespace fosls {
namespace {

struct Row {
  double h, u_h1, sigma_hdiv, functional;
};

/// Least-squares slope of log(err) against log(h).
double fitted_slope(const std::vector<Row>& rows, double Row::*field) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = rows.size();
  for (const auto& r : rows) {
    double x = std::log(r.h), y = std::log(r.*field);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

std::vector<Row> convergence_table(double lambda) {
  testing::SmoothSolution sol;
  std::vector<Row> rows;
  for (int r = 1; r <= 5; ++r) {
    Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.5}), r),
                           sol.problem(lambda));
    const auto& p = disc.problem();
    Eigen::CholmodSupernodalLLT<SparseMatrix> llt(p.qp.A);
    EXPECT_EQ(llt.info(), Eigen::Success);
    Vector x = llt.solve(p.qp.b);
    Vector full = disc.assembler().full_vector(p, x);
    FeField field(disc.finest_space(), full, p.stress_scale);
    ErrorNorms e = error_norms(field, sol.exact());
    double j = disc.assembler().functional(full).total();
    EXPECT_NEAR(j, p.qp.energy(x), 1e-10 * std::max(1.0, j));
    rows.push_back({disc.meshes().finest().edge_length_range().second, e.u_h1, e.sigma_hdiv, j});
    std::printf("lambda=%g h=%.4f dofs=%d |u-uh|_H1=%.3e |s-sh|_Hdiv=%.3e J=%.3e\n", lambda,
                rows.back().h, p.qp.size(), e.u_h1, e.sigma_hdiv, j);
  }
  return rows;
}

TEST(Convergence, SmoothSolutionRatesForLambdaOneAndInfinity) {
  const auto one = convergence_table(1.0);
  const auto inf = convergence_table(std::numeric_limits<double>::infinity());
  for (const auto* t : {&one, &inf}) {
    EXPECT_NEAR(fitted_slope(*t, &Row::u_h1), 1.0, 0.1);
    EXPECT_NEAR(fitted_slope(*t, &Row::sigma_hdiv), 1.0, 0.1);
    EXPECT_NEAR(fitted_slope(*t, &Row::functional), 2.0, 0.1);
  }
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_LT(std::max(one[i].u_h1, inf[i].u_h1) / std::min(one[i].u_h1, inf[i].u_h1), 2.0);
    EXPECT_LT(std::max(one[i].sigma_hdiv, inf[i].sigma_hdiv) /
                  std::min(one[i].sigma_hdiv, inf[i].sigma_hdiv),
              2.0);
  }
  // The finest errors themselves, not just the rates.
  EXPECT_LT(one.back().u_h1, 0.1);
  EXPECT_LT(one.back().sigma_hdiv, 0.5);
}

}  // namespace
}  // namespace fosls
