#pragma once
// An unstructured test mesh: the unit square with its interior vertices moved off the grid.

#include <cmath>

#include "mesh/builtin_meshes.hpp"

namespace fosls::testing {

/// The unit square of mesh size `size` whose interior vertices are moved by up to `amplitude`,
/// so that its triangles are neither all similar nor aligned with the axes.
inline Mesh perturbed_square(double size = 0.2, double amplitude = 0.05) {
  const Mesh sq = make_square({.size = size});
  std::vector<Point> v = sq.vertices();
  for (std::size_t i = 0; i < v.size(); ++i) {
    Point& p = v[i];
    if (p.x() > 0 && p.x() < 1 && p.y() > 0 && p.y() < 1)
      p += amplitude * Point(std::sin(7.0 * i), std::cos(3.0 * i));
  }
  std::vector<std::array<int, 3>> tris;
  for (int t = 0; t < sq.num_triangles(); ++t) tris.push_back(sq.triangle(t));
  std::vector<BoundarySegment> segs;
  for (int e = 0; e < sq.num_edges(); ++e)
    if (sq.is_boundary_edge(e))
      segs.push_back({sq.edge(e)[0], sq.edge(e)[1], sq.edge_group(e), -1});
  return Mesh(v, tris, segs, sq.group_names());
}

}  // namespace fosls::testing
