#pragma once
// Quadrature on a facet — an edge or a triangular face — for boundary data (Neumann fluxes):
// 2D three Gauss–Legendre points (exact for degree 5), 3D the face's edge midpoints (exact for
// degree 2). Weights as fractions of the facet's measure.

#include <array>

#include "mesh/simplex_mesh.hpp"

namespace fosls {

/// Gauss–Legendre on [0, 1], three points, exact for degree 5.
constexpr std::array<double, 3> kEdgeGaussX = {0.1127016653792583, 0.5, 0.8872983346207417};
constexpr std::array<double, 3> kEdgeGaussW = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

template <int dim>
struct FacetQuadrature {
  std::array<Vec<dim>, 3> points;
  std::array<double, 3> weights;  ///< summing to 1
};

template <int dim>
FacetQuadrature<dim> facet_quadrature(const SimplexMesh<dim>& mesh, int f) {
  FacetQuadrature<dim> rule;
  const auto& v = mesh.facet(f);
  if constexpr (dim == 2) {
    const Point a = mesh.vertex(v[0]), b = mesh.vertex(v[1]);
    for (int q = 0; q < 3; ++q) rule.points[q] = a + kEdgeGaussX[q] * (b - a);
    rule.weights = kEdgeGaussW;
  } else {
    for (int k = 0; k < 3; ++k) {
      rule.points[k] = 0.5 * (mesh.vertex(v[k]) + mesh.vertex(v[(k + 1) % 3]));
      rule.weights[k] = 1.0 / 3.0;
    }
  }
  return rule;
}

}  // namespace fosls
