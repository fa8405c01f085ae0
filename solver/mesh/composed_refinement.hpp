#pragma once
// The refinement maps between two levels of a nested hierarchy that are not neighbours, for the
// multilevel solvers' hierarchy that skips close bisection levels (assembly/solver_levels.hpp):
// the maps of the levels between composed into one, in the form the contact links and local
// smoothing read (mesh/refinement.hpp, mesh/tet_refinement.hpp). The parent facets and cells
// always compose. The form's other statement, that every new fine vertex halves an edge of the
// coarse mesh, holds for a vertex unless it halves an edge that a skipped level made; such a
// vertex gets no parents (midpoint_edge −1 in 2D, midpoint_ends {−1, −1} in 3D), and maps with
// one are partial: not for cartesian_prolongation (the transfer between the levels is then the
// product of the levels' transfers). What every new vertex has instead is its P1 weights over
// the coarse vertices (composed_weights): a chain of midpoints along a coarse edge, or a vertex
// inside a coarse face, is a combination of the coarse facet's vertices.

#include "mesh/refinement.hpp"
#include "mesh/tet_refinement.hpp"

namespace fosls {

/// The maps coarse → fine from `first` (coarse → middle) and `second` (middle → fine).
RefinementMaps compose_refinement_maps(const Mesh& coarse, const Mesh& middle,
                                       const RefinementMaps& first, const RefinementMaps& second);
TetRefinementMaps compose_refinement_maps(const TetMesh& coarse, const TetMesh& middle,
                                          const TetRefinementMaps& first,
                                          const TetRefinementMaps& second);

/// Fine vertex v's P1 weights over the coarse vertices of `maps` (coarse → fine): a coarse
/// vertex itself, the ends of the coarse edge it halves, or the composed weights.
template <class CoarseMesh, class Maps>
CoarseVertexWeights coarse_vertex_weights(const CoarseMesh& coarse, const Maps& maps, int v) {
  CoarseVertexWeights w;
  if (v < maps.num_coarse_vertices) {
    w.vertex[0] = v;
    w.weight[0] = 1.0;
    return w;
  }
  const int k = v - maps.num_coarse_vertices;
  if (!maps.composed_weights.empty()) return maps.composed_weights[k];
  const auto& ends = maps.midpoint_parents(coarse, k);
  w.vertex = {ends[0], ends[1], -1};
  w.weight = {0.5, 0.5, 0.0};
  return w;
}

/// Whether new fine vertex num_coarse_vertices + k halves a coarse edge (always, unless the maps
/// are composed and partial).
inline bool halves_coarse_edge(const RefinementMaps& maps, int k) {
  return maps.midpoint_edge[k] >= 0;
}
inline bool halves_coarse_edge(const TetRefinementMaps& maps, int k) {
  return maps.midpoint_ends[k][0] >= 0;
}

/// Whether every new vertex halves a coarse edge (the maps are complete).
template <class Maps>
bool every_new_vertex_halves_a_coarse_edge(const Maps& maps) {
  for (int k = 0; k < maps.num_midpoints(); ++k)
    if (!halves_coarse_edge(maps, k)) return false;
  return true;
}

}  // namespace fosls
