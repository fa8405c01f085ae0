#include "assembly/patch_blocks.hpp"

#include <algorithm>

namespace fosls {

VertexBlocks two_vertex_blocks(const Mesh& mesh) {
  const int nv = mesh.num_vertices();
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const Point& p : mesh.vertices())
    for (int c = 0; c < 2; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
  const int axis = hi[0] - lo[0] >= hi[1] - lo[1] ? 0 : 1;
  std::vector<int> by_coordinate(nv);
  for (int v = 0; v < nv; ++v) by_coordinate[v] = v;
  std::nth_element(by_coordinate.begin(), by_coordinate.begin() + nv / 2, by_coordinate.end(),
                   [&](int a, int b) { return mesh.vertex(a)[axis] < mesh.vertex(b)[axis]; });
  // 0: block 0, 1: block 1, 2: separator.
  std::vector<char> block(nv, 1);
  for (int k = 0; k < nv / 2; ++k) block[by_coordinate[k]] = 0;
  for (char layer = 0; layer < 2; ++layer) {
    // Vertices of block 1 next to block 0 (first layer) or to the first layer (second).
    const char from = layer == 0 ? 0 : 3;
    for (int e = 0; e < mesh.num_edges(); ++e) {
      const auto& ab = mesh.edge(e);
      for (int s = 0; s < 2; ++s)
        if (block[ab[s]] == from && block[ab[1 - s]] == 1) block[ab[1 - s]] = layer == 0 ? 3 : 4;
    }
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
