#include "fem/simplex_element.hpp"

#include <Eigen/Dense>

namespace fosls {

namespace {

/// ∇λ_k on a triangle: R⁻¹(a_{k+2} − a_{k+1}) / (2|T|), R the clockwise rotation by 90°.
void triangle_gradients(SimplexElement<2>& e) {
  for (int k = 0; k < 3; ++k) {
    const Point& p = e.a[(k + 1) % 3];
    const Point& q = e.a[(k + 2) % 3];
    e.grad[k] = Point(p.y() - q.y(), q.x() - p.x()) / (2.0 * e.measure);
  }
}

/// ∇λ_k on a tetrahedron: the rows of the inverse of the edge matrix (a_1 − a_0, a_2 − a_0,
/// a_3 − a_0) give ∇λ_1 … ∇λ_3, and the λ_k sum to 1.
void tetrahedron_gradients(SimplexElement<3>& e) {
  Eigen::Matrix3d m;
  for (int k = 0; k < 3; ++k) m.col(k) = e.a[k + 1] - e.a[0];
  const Eigen::Matrix3d inv = m.inverse();
  e.grad[0] = Point3::Zero();
  for (int k = 0; k < 3; ++k) {
    e.grad[k + 1] = inv.row(k).transpose();
    e.grad[0] -= e.grad[k + 1];
  }
}

}  // namespace

template <int dim>
SimplexElement<dim>::SimplexElement(const SimplexMesh<dim>& mesh, int t) {
  for (int k = 0; k <= dim; ++k) {
    a[k] = mesh.vertex(mesh.cell(t)[k]);
    s[k] = mesh.cell_facet_sign(t, k);
  }
  measure = mesh.cell_measure(t);
  if constexpr (dim == 2)
    triangle_gradients(*this);
  else
    tetrahedron_gradients(*this);
}

template <int dim>
std::array<Vec<dim>, dim + 1> SimplexElement<dim>::quadrature_points() const {
  std::array<Vec<dim>, dim + 1> x;
  if constexpr (dim == 2) {
    for (int q = 0; q < 3; ++q) x[q] = 0.5 * (a[(q + 1) % 3] + a[(q + 2) % 3]);
  } else {
    // Barycentric (α, β, β, β) and its permutations.
    constexpr double alpha = 0.5854101966249685, beta = 0.1381966011250105;
    for (int q = 0; q < 4; ++q) {
      x[q] = Point3::Zero();
      for (int k = 0; k < 4; ++k) x[q] += (k == q ? alpha : beta) * a[k];
    }
  }
  return x;
}

template struct SimplexElement<2>;
template struct SimplexElement<3>;

}  // namespace fosls
