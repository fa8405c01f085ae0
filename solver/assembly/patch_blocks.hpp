#pragma once
// The order of the vertex patches for a smoother sweep on two threads: two blocks
// of vertices that are at least three edges apart, so that no patch of one block reads or
// writes an entry of x or r that a patch of the other writes, and the separator between
// them. Sweeping block 0 and block 1 at the same time and then the separator gives exactly
// the iterate of the sequential sweep in the order [block 0, block 1, separator]: the method
// stays monotone, the result is the same bit for bit on one or two threads, and the threads
// meet once per sweep.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/tet_mesh.hpp"

namespace fosls {

struct VertexBlocks {
  std::vector<int> order;     ///< all vertices: block 0, block 1, separator
  std::array<int, 2> ends{};  ///< end of block 0 and of block 1 in `order`
};

/// Splits the vertices at the median of the coordinate with the largest extent and moves the
/// vertices of the upper half within two edges of the lower half into the separator: on the
/// triangles' edges, or on the tetrahedra's vertex pairs.
VertexBlocks two_vertex_blocks(const Mesh& mesh);
VertexBlocks two_vertex_blocks(const TetMesh& mesh);

/// The same for any mesh: vertex v at `points[v]` (2 or 3 coordinates), `edges` the pairs of
/// vertices that share a cell, in a fixed order (the tetrahedral meshes' vertex stars).
VertexBlocks two_vertex_blocks(const std::vector<Eigen::VectorXd>& points,
                               const std::vector<std::array<int, 2>>& edges);

}  // namespace fosls
