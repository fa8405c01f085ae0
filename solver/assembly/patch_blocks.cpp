#include "assembly/patch_blocks.hpp"

#include <algorithm>

namespace fosls {

VertexBlocks two_vertex_blocks(const Mesh& mesh) {
  std::vector<Eigen::VectorXd> points;
  points.reserve(mesh.num_vertices());
  for (const Point& p : mesh.vertices()) points.emplace_back(p);
  std::vector<std::array<int, 2>> edges;
  edges.reserve(mesh.num_edges());
  for (int e = 0; e < mesh.num_edges(); ++e) edges.push_back(mesh.edge(e));
  return two_vertex_blocks(points, edges);
}

VertexBlocks two_vertex_blocks(const TetMesh& mesh) {
  // The vertex pairs of the tetrahedra, sorted: a tetrahedral mesh keeps no edge list.
  std::vector<std::array<int, 2>> edges;
  edges.reserve(6 * mesh.num_tets());
  for (int t = 0; t < mesh.num_tets(); ++t)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        edges.push_back(
            {std::min(mesh.tet(t)[i], mesh.tet(t)[j]), std::max(mesh.tet(t)[i], mesh.tet(t)[j])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<Eigen::VectorXd> points;
  points.reserve(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v) points.emplace_back(mesh.vertex(v));
  return two_vertex_blocks(points, edges);
}

VertexBlocks two_vertex_blocks(const std::vector<Eigen::VectorXd>& points,
                               const std::vector<std::array<int, 2>>& edges) {
  const int nv = static_cast<int>(points.size());
  const int dims = nv > 0 ? static_cast<int>(points[0].size()) : 0;
  int axis = 0;
  double widest = -1.0;
  for (int c = 0; c < dims; ++c) {
    double lo = 1e300, hi = -1e300;
    for (const auto& p : points) lo = std::min(lo, p[c]), hi = std::max(hi, p[c]);
    if (hi - lo > widest) widest = hi - lo, axis = c;  // the first of equal extents
  }
  std::vector<int> by_coordinate(nv);
  for (int v = 0; v < nv; ++v) by_coordinate[v] = v;
  std::nth_element(by_coordinate.begin(), by_coordinate.begin() + nv / 2, by_coordinate.end(),
                   [&](int a, int b) { return points[a][axis] < points[b][axis]; });
  // 0: block 0, 1: block 1, 2: separator.
  std::vector<char> block(nv, 1);
  for (int k = 0; k < nv / 2; ++k) block[by_coordinate[k]] = 0;
  for (char layer = 0; layer < 2; ++layer) {
    // Vertices of block 1 next to block 0 (first layer) or to the first layer (second).
    const char from = layer == 0 ? 0 : 3;
    for (const auto& ab : edges)
      for (int s = 0; s < 2; ++s)
        if (block[ab[s]] == from && block[ab[1 - s]] == 1) block[ab[1 - s]] = layer == 0 ? 3 : 4;
  }
  VertexBlocks out;
  out.order.reserve(nv);
  for (char b : {0, 1}) {
    for (int v = 0; v < nv; ++v)
      if (block[v] == b) out.order.push_back(v);
    out.ends[b] = static_cast<int>(out.order.size());
  }
  for (int v = 0; v < nv; ++v)
    if (block[v] > 1) out.order.push_back(v);
  return out;
}

}  // namespace fosls
