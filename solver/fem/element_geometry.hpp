#pragma once
// P1 and RT0 on one triangle: the local formulas of docs/method.md §3 in one place.
//
// Triangle T with counter-clockwise vertices a_0, a_1, a_2, edge e_k opposite a_k.
// P1:  φ_k linear with φ_k(a_j) = δ_kj, ∇φ_k = R⁻¹(a_{k+2} − a_{k+1}) / (2|T|).
// RT0: ψ_k(x) = s_k (x − a_k) / (2|T|), div ψ_k = s_k / |T|, flux of ψ_k through e_k (with the
//      global normal of e_k) = 1; s_k = ±1 the agreement of global and local outward normal.

#include <array>

#include "mesh/mesh.hpp"

namespace fosls {

struct ElementGeometry {
  std::array<Point, 3> a;
  std::array<double, 3> s;
  double area = 0.0;

  ElementGeometry(const Mesh& mesh, int t) {
    const auto& tri = mesh.triangle(t);
    for (int k = 0; k < 3; ++k) {
      a[k] = mesh.vertex(tri[k]);
      s[k] = mesh.triangle_edge_sign(t, k);
    }
    area = mesh.triangle_area(t);
  }

  /// Gradient of the P1 basis function of vertex k.
  Point grad_p1(int k) const {
    const Point& p = a[(k + 1) % 3];
    const Point& q = a[(k + 2) % 3];
    return Point(p.y() - q.y(), q.x() - p.x()) / (2.0 * area);
  }
  /// Value of the P1 basis function of vertex k at x.
  double p1(int k, const Point& x) const { return 1.0 + grad_p1(k).dot(x - a[k]); }
  /// Value of the RT0 basis function of edge k at x.
  Point rt0(int k, const Point& x) const { return s[k] * (x - a[k]) / (2.0 * area); }
  /// Divergence of the RT0 basis function of edge k.
  double rt0_div(int k) const { return s[k] / area; }
  /// Midpoint of edge k (the quadrature points of the rule exact for degree 2).
  Point edge_midpoint(int k) const { return 0.5 * (a[(k + 1) % 3] + a[(k + 2) % 3]); }
};

}  // namespace fosls
