// Three dimensions, stage 1 (docs/method.md §11): the FOSLS discretisation P1 × RT0 on
// tetrahedra converges for a smooth manufactured solution at the rates of 2D (1 in H1 and
// H(div), 2 for J) for λ = 1 and λ = ∞, and the multilevel method with vertex-patch smoothing
// solves it in as many iterations on every level.
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <cmath>
#include <cstdio>
#include <limits>

#include "../tet_problems.hpp"
#include "assembly/tet_hierarchy.hpp"
#include "fem/simplex_element.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

/// u = (sin πy sin πz, sin πz sin πx, sin πx sin πy): divergence free, so σ = 2μ ε(u) is the
/// solution for every λ (pressure 0 at λ = ∞), and f = −div σ = −μ Δu = 2π² μ u.
struct SmoothSolution3 {
  static Point3 u(const Point3& p) {
    const double x = M_PI * p.x(), y = M_PI * p.y(), z = M_PI * p.z();
    return {std::sin(y) * std::sin(z), std::sin(z) * std::sin(x), std::sin(x) * std::sin(y)};
  }
  static Eigen::Matrix3d grad_u(const Point3& p) {
    const double x = M_PI * p.x(), y = M_PI * p.y(), z = M_PI * p.z();
    Eigen::Matrix3d g;  // g(i, j) = ∂_j u_i
    g << 0, M_PI * std::cos(y) * std::sin(z), M_PI * std::sin(y) * std::cos(z),
        M_PI * std::sin(z) * std::cos(x), 0, M_PI * std::cos(z) * std::sin(x),
        M_PI * std::cos(x) * std::sin(y), M_PI * std::sin(x) * std::cos(y), 0;
    return g;
  }
  static Eigen::Matrix3d sigma(const Point3& p) {
    const Eigen::Matrix3d g = grad_u(p);
    return g + g.transpose();  // μ = 1
  }
  static Point3 f(const Point3& p) { return 2.0 * M_PI * M_PI * u(p); }

  /// Dirichlet on left, front and bottom, Neumann (t = σn) on right, back and top.
  static ProblemData<3> problem(double lambda) {
    ProblemData<3> d;
    d.material = {.mu = 1.0, .lambda = lambda};
    for (int i = 0; i < 3; ++i)
      d.body_force[i] = testing::of_point([i](const Point3& x) { return f(x)[i]; });
    d.groups.resize(6);  // left, right, front, back, bottom, top
    for (int g = 0; g < 6; ++g) {
      const bool dirichlet = g % 2 == 0;
      Point3 n = Point3::Zero();
      n[g / 2] = 1.0;
      d.groups[g].role = dirichlet ? GroupRole::kDirichlet : GroupRole::kNeumann;
      for (int i = 0; i < 3; ++i)
        d.groups[g].values[i] =
            dirichlet ? testing::of_point([i](const Point3& x) { return u(x)[i]; })
                      : testing::of_point([i, n](const Point3& x) { return (sigma(x) * n)[i]; });
    }
    return d;
  }
};

struct Row {
  int dofs = 0;
  double h = 0, u_h1 = 0, sigma_hdiv = 0, functional = 0;
  int iterations = 0;
};

/// ‖u − u_h‖_H1 and ‖σ − σ_h‖_H(div) by the four-point rule.
std::pair<double, double> error_norms(const FoslsSpace<3>& space, const Vector& x, double scale) {
  double eu = 0, es = 0;
  const TetMesh& mesh = space.mesh();
  for (int t = 0; t < mesh.num_tets(); ++t) {
    const SimplexElement<3> e(mesh, t);
    const auto dofs = space.cell_dofs(t);
    Eigen::Matrix3d grad = Eigen::Matrix3d::Zero();
    Point3 div = Point3::Zero();
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 3; ++c) {
        grad.row(c) += x[dofs[3 * k + c]] * e.grad[k].transpose();
        div[c] += scale * x[dofs[12 + 3 * k + c]] * e.rt0_div(k);
      }
    for (const Point3& q : e.quadrature_points()) {
      Point3 u = Point3::Zero();
      Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
      for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) {
          u[c] += e.p1(k, q) * x[dofs[3 * k + c]];
          sigma.row(c) += scale * x[dofs[12 + 3 * k + c]] * e.rt0(k, q).transpose();
        }
      const double w = 0.25 * e.measure;
      eu += w * ((u - SmoothSolution3::u(q)).squaredNorm() +
                 (grad - SmoothSolution3::grad_u(q)).squaredNorm());
      es += w * ((sigma - SmoothSolution3::sigma(q)).squaredNorm() +
                 (div + SmoothSolution3::f(q)).squaredNorm());
    }
  }
  return {std::sqrt(eu), std::sqrt(es)};
}

std::vector<Row> convergence_table(double lambda, int finest) {
  std::vector<Row> rows;
  for (int r = 1; r <= finest; ++r) {
    const TetDiscretization disc(build_tet_hierarchy(make_box({2, 2, 2}), r),
                                 SmoothSolution3::problem(lambda));
    const AssembledProblem& p = disc.problem();
    Eigen::CholmodSupernodalLLT<SparseMatrix> llt(p.qp.A);
    EXPECT_EQ(llt.info(), Eigen::Success);
    const Vector exact = llt.solve(p.qp.b);
    Row row;
    row.dofs = p.qp.size();
    row.h = 0.5 / (1 << r);
    const Vector full = disc.assembler().full_vector(p, exact);
    std::tie(row.u_h1, row.sigma_hdiv) = error_norms(disc.finest_space(), full, p.stress_scale);
    row.functional = disc.assembler().functional(full).total();
    EXPECT_NEAR(row.functional, p.qp.energy(exact), 1e-9 * std::max(1.0, row.functional));
    // The multilevel method from zero to a relative KKT residual of 1e-8.
    SolverOptions options;
    Vector x = Vector::Zero(p.qp.size());
    const SolverReport report = solve_box_qp(p.qp, disc.build_level_hierarchy(), options, {}, x);
    EXPECT_TRUE(report.converged) << r;
    row.iterations = report.iterations;
    EXPECT_LT((x - exact).norm(), 1e-5 * exact.norm()) << r;
    std::printf("lambda=%g r=%d dofs=%d |u-uh|_H1=%.3e |s-sh|_Hdiv=%.3e J=%.3e mmg %d\n", lambda, r,
                row.dofs, row.u_h1, row.sigma_hdiv, row.functional, row.iterations);
    rows.push_back(row);
  }
  return rows;
}

double slope(const Row& a, const Row& b, double Row::*field) {
  return std::log(a.*field / b.*field) / std::log(a.h / b.h);
}

TEST(TetConvergence, RatesAndFlatIterationsForLambdaOneAndInfinity) {
  for (double lambda : {1.0, std::numeric_limits<double>::infinity()}) {
    const auto rows = convergence_table(lambda, 3);
    const Row& a = rows[rows.size() - 2];
    const Row& b = rows.back();
    EXPECT_NEAR(slope(a, b, &Row::u_h1), 1.0, 0.15) << lambda;
    EXPECT_NEAR(slope(a, b, &Row::sigma_hdiv), 1.0, 0.15) << lambda;
    EXPECT_NEAR(slope(a, b, &Row::functional), 2.0, 0.2) << lambda;
    for (const Row& row : rows) EXPECT_LE(row.iterations, rows.front().iterations + 3) << lambda;
  }
}

}  // namespace
}  // namespace fosls
