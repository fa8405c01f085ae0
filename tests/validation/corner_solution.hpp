#pragma once
// A manufactured solution with the corner singularity of the L-shaped domain
// (−1, 1)² \ [0, 1) × (−1, 0], whose re-entrant corner of 270° is the origin
// (docs/validation.md §11).
//
// u = ∇φ with φ = Re z^(5/3) = r^(5/3) cos(5θ/3), θ ∈ [0, 3π/2] measured from the edge
// y = 0, x > 0 through the body. φ is harmonic, so div u = Δφ = 0 and Δu = ∇Δφ = 0: u solves
// the Navier–Lamé equations with f = 0 for every λ (λ = ∞ included, with pressure 0), and
// σ = 2μ ε(u) = 2μ ∇∇φ. u ~ r^(2/3) and σ ~ r^(−1/3), as the Laplace L-shape singularity:
// u ∈ H^(1+2/3−ε) only, so uniform refinement converges as h^(2/3) = N^(−1/3) and an optimal
// adaptive method as N^(−1/2). Dirichlet data u on the left and bottom sides and on the two
// edges at the corner, Neumann data t = σn on the right and top sides (smooth there).

#include <array>
#include <cmath>
#include <complex>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "assembly/problem_data.hpp"
#include "mesh/mesh.hpp"
#include "post/fe_field.hpp"

namespace fosls::testing {

struct CornerSolution {
  double mu = 1.0;
  /// φ = Re z^beta; 5/3 gives the corner singularity, 2 (u linear) a check of the set-up.
  double beta = 5.0 / 3.0;

  /// z^a = r^a e^(iaθ) with θ on the branch of the body, [0, 3π/2] (std::pow would take
  /// θ in (−π, π] and cut the body along the negative x axis).
  static std::complex<double> power(const Point& p, double a) {
    double theta = std::atan2(p.y(), p.x());
    if (theta < 0) theta += 2 * M_PI;
    return std::polar(std::pow(std::hypot(p.x(), p.y()), a), a * theta);
  }
  /// φ_x − i φ_y = F'(z) = β z^(β−1).
  Eigen::Vector2d u(const Point& p) const {
    const std::complex<double> d = beta * power(p, beta - 1);
    return {d.real(), -d.imag()};
  }
  /// ∇∇φ = [Re F'', −Im F''; −Im F'', −Re F''] with F'' = β(β−1) z^(β−2); taken as 0 at the
  /// corner, where it is infinite for β < 2 (a quadrature never evaluates it there).
  Eigen::Matrix2d grad_u(const Point& p) const {
    if (p.norm() == 0.0 && beta < 2) return Eigen::Matrix2d::Zero();
    const std::complex<double> dd = beta * (beta - 1) * power(p, beta - 2);
    Eigen::Matrix2d g;
    g << dd.real(), -dd.imag(), -dd.imag(), -dd.real();
    return g;
  }
  Eigen::Matrix2d sigma(const Point& p) const { return 2.0 * mu * grad_u(p); }

  ExactSolution exact() const {
    return {[this](const Point& p) { return u(p); }, [this](const Point& p) { return grad_u(p); },
            [this](const Point& p) { return sigma(p); },
            [](const Point&) -> Eigen::Vector2d { return Eigen::Vector2d::Zero(); }};
  }

  /// Groups of corner_mesh: 0 Dirichlet (left, bottom, the corner's edges), 1 right, 2 top.
  ProblemData<2> problem(double lambda) const {
    ProblemData<2> d;
    d.material.mu = mu;
    d.material.lambda = lambda;
    for (int i = 0; i < 2; ++i) d.body_force[i] = [](double, double) { return 0.0; };
    d.groups.resize(3);
    d.groups[0].role = GroupRole::kDirichlet;
    for (int i = 0; i < 2; ++i)
      d.groups[0].values[i] = [this, i](double x, double y) { return u({x, y})[i]; };
    const std::array<Point, 2> normals = {Point(1, 0), Point(0, 1)};
    for (int g = 1; g < 3; ++g) {
      d.groups[g].role = GroupRole::kNeumann;
      for (int i = 0; i < 2; ++i)
        d.groups[g].values[i] = [this, i, n = normals[g - 1]](double x, double y) {
          return (sigma({x, y}) * n)[i];
        };
    }
    return d;
  }
};

/// The L-shaped domain in squares of side 1/n, each cut along its rising diagonal; groups
/// "dirichlet", "right", "top" as CornerSolution::problem expects.
inline Mesh corner_mesh(int n) {
  const int m = 2 * n;
  auto removed_cell = [n](int i, int j) { return i >= n && j < n; };
  std::vector<Point> vertices;
  std::map<std::pair<int, int>, int> index;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i)
      if (!(i > n && j < n)) {
        index[{i, j}] = static_cast<int>(vertices.size());
        vertices.emplace_back(double(i) / n - 1.0, double(j) / n - 1.0);
      }
  std::vector<std::array<int, 3>> triangles;
  std::map<std::pair<int, int>, int> side_count;  // each cell side, by its two vertices
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      if (removed_cell(i, j)) continue;
      const int a = index.at({i, j}), b = index.at({i + 1, j}), c = index.at({i + 1, j + 1}),
                d = index.at({i, j + 1});
      triangles.push_back({a, b, c});
      triangles.push_back({a, c, d});
      for (auto [p, q] : {std::pair{a, b}, {b, c}, {d, c}, {a, d}}) ++side_count[{p, q}];
    }
  std::vector<BoundarySegment> segments;
  for (const auto& [side, count] : side_count) {
    if (count != 1) continue;
    const Point mid = 0.5 * (vertices[side.first] + vertices[side.second]);
    const int group = mid.x() == 1.0 ? 1 : mid.y() == 1.0 ? 2 : 0;
    segments.push_back({side.first, side.second, group, -1});
  }
  return Mesh(std::move(vertices), std::move(triangles), std::move(segments),
              {"dirichlet", "right", "top"});
}

}  // namespace fosls::testing
