#include "mesh/refinement.hpp"

#include <stdexcept>

namespace fosls {

Refinement refine_uniformly(const Mesh& coarse) {
  const int nv = coarse.num_vertices();
  const int ne = coarse.num_edges();
  std::vector<Point> vertices(coarse.vertices());
  vertices.reserve(nv + ne);
  for (int e = 0; e < ne; ++e) {
    Point m = coarse.edge_midpoint(e);
    int c = coarse.edge_curve(e);
    if (c >= 0) m = coarse.curves()[c].project(m);
    vertices.push_back(m);
  }
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(4 * static_cast<std::size_t>(coarse.num_triangles()));
  for (int t = 0; t < coarse.num_triangles(); ++t) {
    const auto& a = coarse.triangle(t);
    const int m0 = nv + coarse.triangle_edge(t, 0);
    const int m1 = nv + coarse.triangle_edge(t, 1);
    const int m2 = nv + coarse.triangle_edge(t, 2);
    triangles.push_back({a[0], m2, m1});
    triangles.push_back({a[1], m0, m2});
    triangles.push_back({a[2], m1, m0});
    triangles.push_back({m0, m1, m2});
  }
  std::vector<BoundarySegment> segments;
  for (int e = 0; e < ne; ++e) {
    if (!coarse.is_boundary_edge(e)) continue;
    const auto& pq = coarse.edge(e);
    segments.push_back({pq[0], nv + e, coarse.edge_group(e), coarse.edge_curve(e)});
    segments.push_back({nv + e, pq[1], coarse.edge_group(e), coarse.edge_curve(e)});
  }
  Refinement out{Mesh(std::move(vertices), std::move(triangles), std::move(segments),
                      coarse.group_names(), coarse.curves()),
                 {}};
  const Mesh& fine = out.fine;
  auto& maps = out.maps;
  maps.num_coarse_vertices = nv;
  maps.midpoint_edge.resize(ne);
  for (int e = 0; e < ne; ++e) maps.midpoint_edge[e] = e;
  maps.triangle_parent.resize(fine.num_triangles());
  for (int t = 0; t < fine.num_triangles(); ++t) maps.triangle_parent[t] = t / 4;
  const int nfe = fine.num_edges();
  maps.parent_edge.assign(nfe, -1);
  maps.parent_triangle.assign(nfe, -1);
  maps.parent_sign.assign(nfe, 0);
  for (int f = 0; f < nfe; ++f) {
    int p = fine.edge(f)[0], q = fine.edge(f)[1];
    if (p < nv || q < nv) {
      // A half of a coarse edge: one end is a coarse vertex, the other a midpoint.
      int e = (p < nv) ? q - nv : p - nv;
      maps.parent_edge[f] = e;
      // Orientation agreement is topological: the fine edge runs along the coarse one.
      const auto& ce = coarse.edge(e);
      bool forward = (p == ce[0] || q == ce[1]);
      maps.parent_sign[f] = forward ? 1 : -1;
    } else {
      int e1 = p - nv, e2 = q - nv;
      const auto& t1 = coarse.edge_triangles(e1);
      const auto& t2 = coarse.edge_triangles(e2);
      int t = -1;
      for (int a : t1)
        for (int b : t2)
          if (a >= 0 && a == b) t = a;
      if (t < 0) throw std::logic_error("refinement: interior fine edge without parent triangle");
      maps.parent_triangle[f] = t;
    }
  }
  return out;
}

MeshHierarchy build_mesh_hierarchy(Mesh coarse, int refinements) {
  return refine_repeatedly<Mesh, RefinementMaps>(std::move(coarse), refinements, refine_uniformly);
}

}  // namespace fosls
