#pragma once
// Problems with known solutions shared by the verification tests.

#include <cmath>
#include <limits>

#include "assembly/discretization.hpp"
#include "mesh/builtin_meshes.hpp"
#include "post/fe_field.hpp"

namespace fosls::testing {

/// Divergence-free u = (sin πx cos πy, −cos πx sin πy) with σ = 2μ ε(u): the exact solution
/// for every λ, including λ = ∞ (with pressure 0), and f = −div σ = 2π²μ u.
struct SmoothSolution {
  double mu = 1.0;
  Eigen::Vector2d u(const Point& p) const {
    const double x = M_PI * p.x(), y = M_PI * p.y();
    return {std::sin(x) * std::cos(y), -std::cos(x) * std::sin(y)};
  }
  Eigen::Matrix2d grad_u(const Point& p) const {
    const double x = M_PI * p.x(), y = M_PI * p.y();
    Eigen::Matrix2d g;
    g << M_PI * std::cos(x) * std::cos(y), -M_PI * std::sin(x) * std::sin(y),
        M_PI * std::sin(x) * std::sin(y), -M_PI * std::cos(x) * std::cos(y);
    return g;
  }
  Eigen::Matrix2d sigma(const Point& p) const {
    Eigen::Matrix2d g = grad_u(p);
    return mu * (g + g.transpose());
  }
  Eigen::Vector2d f(const Point& p) const { return 2.0 * M_PI * M_PI * mu * u(p); }

  ExactSolution exact() const {
    return {[this](const Point& p) { return u(p); }, [this](const Point& p) { return grad_u(p); },
            [this](const Point& p) { return sigma(p); },
            [this](const Point& p) -> Eigen::Vector2d { return -f(p); }};
  }

  /// Unit square, Dirichlet on left and bottom, Neumann (t = σn) on right and top.
  ProblemData<2> problem(double lambda) const {
    ProblemData<2> d;
    d.material.mu = mu;
    d.material.lambda = lambda;
    for (int i = 0; i < 2; ++i)
      d.body_force[i] = [this, i](double x, double y) { return f({x, y})[i]; };
    d.groups.resize(4);  // bottom, right, top, left
    const std::array<Point, 4> normals = {Point(0, -1), Point(1, 0), Point(0, 1), Point(-1, 0)};
    for (int g = 0; g < 4; ++g) {
      const bool dirichlet = g == 0 || g == 3;
      d.groups[g].role = dirichlet ? GroupRole::kDirichlet : GroupRole::kNeumann;
      for (int i = 0; i < 2; ++i) {
        Point n = normals[g];
        if (dirichlet)
          d.groups[g].values[i] = [this, i](double x, double y) { return u({x, y})[i]; };
        else
          d.groups[g].values[i] = [this, i, n](double x, double y) {
            return (sigma({x, y}) * n)[i];
          };
      }
    }
    return d;
  }
};

}  // namespace fosls::testing
