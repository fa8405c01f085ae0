// Convergence of the order-2 discretisation P2 × RT1 (docs/method.md §10) for the smooth
// manufactured solution of convergence_test.cpp: errors O(h²) in H1 and H(div), J O(h⁴), for
// λ = 1 and λ = ∞.
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <cstdio>

#include "assembly/p2_rt1_assembler.hpp"
#include "fem/p2_rt1_element.hpp"
#include "verification_problems.hpp"

namespace fosls {
namespace {

struct Row {
  double h, u_h1, sigma_hdiv, functional;
};

double slope(const Row& coarse, const Row& fine, double Row::*field) {
  return std::log(coarse.*field / fine.*field) / std::log(coarse.h / fine.h);
}

/// ‖u − u_h‖_H1 and ‖σ − σ_h‖_H(div) by the degree-5 rule on every triangle.
std::pair<double, double> error_norms(const P2Rt1Space& space, const Vector& x_cartesian,
                                      double stress_scale, const testing::SmoothSolution& sol) {
  const Mesh& mesh = space.mesh();
  double eu = 0.0, es = 0.0;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const P2Rt1Element el(mesh, t);
    const auto dofs = space.cell_dofs(t);
    for (const TrianglePoint& p : kTriangleDegree5) {
      const Point x = el.point(p.l0, p.l1);
      const double w = p.weight * el.area();
      const auto phi = el.p2(x);
      const auto grad = el.p2_gradients(x);
      const auto psi = el.rt1(x);
      const auto div = el.rt1_divergences(x);
      Eigen::Vector2d u = Eigen::Vector2d::Zero(), div_sigma = Eigen::Vector2d::Zero();
      Eigen::Matrix2d grad_u = Eigen::Matrix2d::Zero(), sigma = Eigen::Matrix2d::Zero();
      for (int n = 0; n < 6; ++n)
        for (int c = 0; c < 2; ++c) {
          u[c] += phi[n] * x_cartesian[dofs[2 * n + c]];
          grad_u.row(c) += x_cartesian[dofs[2 * n + c]] * grad[n].transpose();
        }
      for (int m = 0; m < 8; ++m)
        for (int i = 0; i < 2; ++i) {
          const double s = stress_scale * x_cartesian[dofs[12 + 2 * m + i]];
          sigma.row(i) += s * psi[m].transpose();
          div_sigma[i] += s * div[m];
        }
      eu += w * ((u - sol.u(x)).squaredNorm() + (grad_u - sol.grad_u(x)).squaredNorm());
      es += w * ((sigma - sol.sigma(x)).squaredNorm() + (div_sigma + sol.f(x)).squaredNorm());
    }
  }
  return {std::sqrt(eu), std::sqrt(es)};
}

std::vector<Row> convergence_table(double lambda) {
  testing::SmoothSolution sol;
  std::vector<Row> rows;
  for (int r = 0; r <= 4; ++r) {
    const MeshHierarchy meshes = build_mesh_hierarchy(make_square({.size = 0.5}), r);
    const ProblemData<2> data = sol.problem(lambda);
    const P2Rt1Space space(meshes.finest(), data.boundary_roles());
    const P2Rt1Assembler assembler(space, data);
    const AssembledProblem p = assembler.assemble_system();
    Eigen::CholmodSupernodalLLT<SparseMatrix> llt(p.qp.A);
    EXPECT_EQ(llt.info(), Eigen::Success);
    const Vector x = llt.solve(p.qp.b);
    const Vector full = assembler.full_vector(p, x);
    const double j = assembler.functional(full).total();
    EXPECT_NEAR(j, p.qp.energy(x), 1e-9 * std::max(1.0, j));
    const auto [u_h1, sigma_hdiv] =
        error_norms(space, space.rotation() * full, p.stress_scale, sol);
    rows.push_back({meshes.finest().edge_length_range().second, u_h1, sigma_hdiv, j});
    std::printf("lambda=%g h=%.4f dofs=%d |u-uh|_H1=%.3e |s-sh|_Hdiv=%.3e J=%.3e\n", lambda,
                rows.back().h, p.qp.size(), u_h1, sigma_hdiv, j);
  }
  return rows;
}

TEST(Order2Convergence, SmoothSolutionRatesForLambdaOneAndInfinity) {
  for (double lambda : {1.0, std::numeric_limits<double>::infinity()}) {
    const auto rows = convergence_table(lambda);
    const Row& a = rows[rows.size() - 2];
    const Row& b = rows.back();
    EXPECT_NEAR(slope(a, b, &Row::u_h1), 2.0, 0.15) << lambda;
    EXPECT_NEAR(slope(a, b, &Row::sigma_hdiv), 2.0, 0.15) << lambda;
    EXPECT_NEAR(slope(a, b, &Row::functional), 4.0, 0.3) << lambda;
    EXPECT_LT(b.u_h1, 0.005) << lambda;  // the finest error itself, not just the rates
  }
}

}  // namespace
}  // namespace fosls
