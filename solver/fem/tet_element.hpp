#pragma once
// P1 and RT0 on one tetrahedron (docs/method.md §11): the local formulas of element_geometry.hpp
// in three dimensions.
//
// Tetrahedron T with vertices a_0 … a_3, face f_k opposite a_k, s_k = ±1 the agreement of the
// face's global normal with T's outward normal there.
// P1:  λ_k linear with λ_k(a_j) = δ_kj.
// RT0: ψ_k(x) = s_k (x − a_k) / (3|T|), div ψ_k = s_k / |T|, flux of ψ_k through f_k (with its
//      global normal) = 1 and through the other faces 0.

#include <Eigen/Dense>
#include <array>

#include "mesh/tet_mesh.hpp"

namespace fosls {

struct TetElement {
  std::array<Point3, 4> a;
  std::array<double, 4> s;
  std::array<Point3, 4> grad;  ///< ∇λ_k
  double volume = 0.0;

  TetElement(const TetMesh& mesh, int t) {
    const auto& v = mesh.tet(t);
    for (int k = 0; k < 4; ++k) a[k] = mesh.vertex(v[k]);
    volume = mesh.tet_volume(t);
    Eigen::Matrix3d m;
    for (int k = 0; k < 3; ++k) m.col(k) = a[k + 1] - a[0];
    const Eigen::Matrix3d inv = m.inverse();  // row k: ∇λ_(k+1)
    grad[0] = Point3::Zero();
    for (int k = 0; k < 3; ++k) {
      grad[k + 1] = inv.row(k).transpose();
      grad[0] -= grad[k + 1];
    }
    for (int k = 0; k < 4; ++k) {
      const int f = mesh.tet_face(t, k);
      s[k] = mesh.face_normal(f).dot(mesh.face_centroid(f) - a[k]) > 0 ? 1.0 : -1.0;
    }
  }

  double p1(int k, const Point3& x) const { return 1.0 + grad[k].dot(x - a[k]); }
  Point3 rt0(int k, const Point3& x) const { return s[k] * (x - a[k]) / (3.0 * volume); }
  double rt0_div(int k) const { return s[k] / volume; }
};

/// The four-point rule on a tetrahedron, exact for degree 2: barycentric (α, β, β, β) and its
/// permutations, weight ¼ of the volume each.
inline std::array<Point3, 4> tet_quadrature_points(const TetElement& e) {
  constexpr double alpha = 0.5854101966249685, beta = 0.1381966011250105;
  std::array<Point3, 4> x;
  for (int q = 0; q < 4; ++q) {
    x[q] = Point3::Zero();
    for (int k = 0; k < 4; ++k) x[q] += (k == q ? alpha : beta) * e.a[k];
  }
  return x;
}

}  // namespace fosls
