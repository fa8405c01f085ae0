#pragma once
// P1 and RT0 on one simplex, a triangle (dim = 2) or a tetrahedron (dim = 3): the local
// formulas of docs/method.md §3 and §11, written once.
//
// Simplex T with vertices a_0 … a_d, facet f_k opposite a_k, s_k = ±1 the agreement of the
// global normal of f_k with T's outward normal there.
// P1:  λ_k linear with λ_k(a_j) = δ_kj.
// RT0: ψ_k(x) = s_k (x − a_k) / (d |T|), div ψ_k = s_k / |T|, flux of ψ_k through f_k (with its
//      global normal) 1 and through the other facets 0.
// Quadrature, exact for degree 2 (every integrand of the functional): the edge midpoints on a
// triangle, the four-point rule on a tetrahedron; weight |T| / (d + 1) each.

#include <array>

#include "mesh/simplex_mesh.hpp"

namespace fosls {

template <int dim>
struct SimplexElement {
  std::array<Vec<dim>, dim + 1> a;
  std::array<double, dim + 1> s;
  std::array<Vec<dim>, dim + 1> grad;  ///< ∇λ_k
  double measure = 0.0;                ///< area or volume

  SimplexElement(const SimplexMesh<dim>& mesh, int t);

  /// Gradient of the P1 basis function of vertex k.
  const Vec<dim>& grad_p1(int k) const { return grad[k]; }
  /// Value of the P1 basis function of vertex k at x.
  double p1(int k, const Vec<dim>& x) const { return 1.0 + grad[k].dot(x - a[k]); }
  /// Value of the RT0 basis function of facet k at x.
  Vec<dim> rt0(int k, const Vec<dim>& x) const { return s[k] * (x - a[k]) / (dim * measure); }
  /// Divergence of the RT0 basis function of facet k.
  double rt0_div(int k) const { return s[k] / measure; }
  /// The points of the rule exact for degree 2, and the weight of each.
  std::array<Vec<dim>, dim + 1> quadrature_points() const;
  double quadrature_weight() const { return measure / (dim + 1); }
};

extern template struct SimplexElement<2>;
extern template struct SimplexElement<3>;

}  // namespace fosls
