#include "mesh/composed_refinement.hpp"

#include <array>

namespace fosls {

namespace {

/// The cell of the coarse mesh that holds a cell of the fine one.
std::vector<int> composed_cell_parents(const std::vector<int>& first,
                                       const std::vector<int>& second) {
  std::vector<int> parent(second.size());
  for (std::size_t t = 0; t < second.size(); ++t) parent[t] = first[second[t]];
  return parent;
}

/// Adds share × w to sum; false when the sum would need a fourth coarse vertex.
bool accumulate(CoarseVertexWeights& sum, const CoarseVertexWeights& w, double share) {
  for (int i = 0; i < 3 && w.vertex[i] >= 0; ++i) {
    int slot = 0;
    while (slot < 3 && sum.vertex[slot] >= 0 && sum.vertex[slot] != w.vertex[i]) ++slot;
    if (slot == 3) return false;
    sum.vertex[slot] = w.vertex[i];
    sum.weight[slot] += share * w.weight[i];
  }
  return true;
}

/// The new fine vertices' weights over the coarse vertices: the middle's new vertices' (first's
/// own), then the fine ones' (second's, over the middle vertices, each replaced by its weights).
template <class SimplexMeshType, class Maps>
std::vector<CoarseVertexWeights> composed_weights(const SimplexMeshType& coarse,
                                                  const SimplexMeshType& middle, const Maps& first,
                                                  const Maps& second) {
  std::vector<CoarseVertexWeights> all;
  all.reserve(first.num_midpoints() + second.num_midpoints());
  for (int k = 0; k < first.num_midpoints(); ++k)
    all.push_back(coarse_vertex_weights(coarse, first, first.num_coarse_vertices + k));
  for (int k = 0; k < second.num_midpoints(); ++k) {
    const CoarseVertexWeights over_middle =
        coarse_vertex_weights(middle, second, second.num_coarse_vertices + k);
    CoarseVertexWeights sum;
    bool fits = over_middle.known();
    for (int i = 0; i < 3 && fits && over_middle.vertex[i] >= 0; ++i)
      fits = accumulate(sum, coarse_vertex_weights(coarse, first, over_middle.vertex[i]),
                        over_middle.weight[i]);
    all.push_back(fits ? sum : CoarseVertexWeights{});
  }
  return all;
}

}  // namespace

RefinementMaps compose_refinement_maps(const Mesh& coarse, const Mesh& middle,
                                       const RefinementMaps& first, const RefinementMaps& second) {
  const int ncv = first.num_coarse_vertices;
  RefinementMaps maps;
  maps.num_coarse_vertices = ncv;
  maps.midpoint_edge = first.midpoint_edge;
  for (const int e : second.midpoint_edge) {
    // An edge of the middle mesh between two coarse vertices is a coarse edge that the first
    // refinement kept (bisection adds edges at new vertices only).
    const std::array<int, 2> ends = e < 0 ? std::array<int, 2>{ncv, ncv} : middle.edge(e);
    maps.midpoint_edge.push_back(ends[0] < ncv && ends[1] < ncv ? first.parent_edge[e] : -1);
  }
  const std::size_t edges = second.parent_edge.size();
  maps.parent_edge.assign(edges, -1);
  maps.parent_triangle.assign(edges, -1);
  maps.parent_sign.assign(edges, 0);
  for (std::size_t f = 0; f < edges; ++f) {
    if (const int p = second.parent_edge[f]; p >= 0) {
      maps.parent_edge[f] = first.parent_edge[p];
      maps.parent_triangle[f] = first.parent_triangle[p];
      maps.parent_sign[f] = static_cast<signed char>(second.parent_sign[f] * first.parent_sign[p]);
    } else {
      maps.parent_triangle[f] = first.triangle_parent[second.parent_triangle[f]];
    }
  }
  maps.triangle_parent = composed_cell_parents(first.triangle_parent, second.triangle_parent);
  maps.composed_weights = composed_weights(coarse, middle, first, second);
  return maps;
}

TetRefinementMaps compose_refinement_maps(const TetMesh& coarse, const TetMesh& middle,
                                          const TetRefinementMaps& first,
                                          const TetRefinementMaps& second) {
  const int ncv = first.num_coarse_vertices;
  TetRefinementMaps maps;
  maps.num_coarse_vertices = ncv;
  maps.midpoint_ends = first.midpoint_ends;
  for (const auto& ends : second.midpoint_ends) {
    const bool coarse_edge = ends[0] >= 0 && ends[0] < ncv && ends[1] >= 0 && ends[1] < ncv;
    maps.midpoint_ends.push_back(coarse_edge ? ends : std::array<int, 2>{-1, -1});
  }
  const std::size_t faces = second.parent_face.size();
  maps.parent_face.assign(faces, -1);
  maps.parent_face_share.assign(faces, 0.0);
  maps.parent_tet_of_face.assign(faces, -1);
  for (std::size_t f = 0; f < faces; ++f) {
    if (const int p = second.parent_face[f]; p >= 0) {
      maps.parent_face[f] = first.parent_face[p];
      if (maps.parent_face[f] >= 0)
        maps.parent_face_share[f] = second.parent_face_share[f] * first.parent_face_share[p];
      maps.parent_tet_of_face[f] = first.parent_tet_of_face[p];
    } else {
      maps.parent_tet_of_face[f] = first.tet_parent[second.parent_tet_of_face[f]];
    }
  }
  maps.tet_parent = composed_cell_parents(first.tet_parent, second.tet_parent);
  maps.composed_weights = composed_weights(coarse, middle, first, second);
  return maps;
}

}  // namespace fosls
