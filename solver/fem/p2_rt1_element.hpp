#pragma once
// P2 and RT1 on one triangle: the local basis of the order-2 space (docs/method.md §10).
//
// Triangle T with counter-clockwise vertices a_0, a_1, a_2, edge e_k opposite a_k, as in
// simplex_element.hpp.
// P2 (6 functions): node k < 3 the vertex a_k, λ_k(2λ_k − 1); node 3 + k the midpoint of e_k,
//     4 λ_{k+1} λ_{k+2}.
// RT1 (8 functions, each of degree 2 with a linear normal component on every edge and a linear
//     divergence): function 2k + j belongs to the end j of edge e_k in the edge's global
//     orientation (p, q): its DOF is |e|/2 · (σ·n_e) at that end, with the global normal n_e,
//     so that the two DOFs of an edge add up to the flux ∫_e σ·n_e ds and RT0's flux S is the
//     pair (S/2, S/2). Functions 6 and 7 belong to the triangle: their DOFs are the means of
//     σ_x and σ_y over T. A field with edge DOFs ≤ 0 has σ·n_e ≤ 0 on the whole edge.
// The basis is the dual basis of these functionals in the monomials of RT1, formed per triangle.

#include <Eigen/Core>
#include <array>

#include "fem/facet_quadrature.hpp"
#include "mesh/mesh.hpp"

namespace fosls {

class P2Rt1Element {
 public:
  P2Rt1Element(const Mesh& mesh, int t);

  double area() const { return area_; }
  const Point& vertex(int k) const { return a_[k]; }
  /// The point with barycentric coordinates (l0, l1, 1 − l0 − l1).
  Point point(double l0, double l1) const;

  /// Values of the six P2 functions at x.
  std::array<double, 6> p2(const Point& x) const;
  /// Gradients of the six P2 functions at x.
  std::array<Point, 6> p2_gradients(const Point& x) const;
  /// Values of the eight RT1 functions at x.
  std::array<Point, 8> rt1(const Point& x) const;
  /// Divergences of the eight RT1 functions at x.
  std::array<double, 8> rt1_divergences(const Point& x) const;

 private:
  /// The eight monomial fields of RT1 at x, in coordinates centred at the centroid and scaled
  /// by the triangle's size (for the conditioning of the dual basis).
  std::array<Point, 8> monomials(const Point& x) const;
  std::array<double, 8> monomial_divergences(const Point& x) const;
  /// Barycentric coordinates of x.
  Eigen::Vector3d barycentric(const Point& x) const;

  std::array<Point, 3> a_;
  double area_ = 0.0;
  Point centre_;
  double scale_ = 1.0;
  std::array<Point, 3> grad_lambda_;
  /// Column m: the coefficients of RT1 function m in the monomials.
  Eigen::Matrix<double, 8, 8> coefficients_;
};

/// A quadrature rule on the reference triangle: barycentric (l0, l1) and the weight as a
/// fraction of the area.
struct TrianglePoint {
  double l0, l1, weight;
};
/// Seven points, exact for degree 5 (Strang–Fix / Dunavant): the order-2 integrands have
/// degree 4.
extern const std::array<TrianglePoint, 7> kTriangleDegree5;

}  // namespace fosls
