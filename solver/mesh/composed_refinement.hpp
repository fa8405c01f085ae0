#pragma once
// The refinement maps between two levels of a nested hierarchy that are not neighbours, for the
// multilevel solvers' hierarchy that skips close bisection levels (assembly/solver_levels.hpp):
// the maps of the levels between composed into one, in the form the contact links and local
// smoothing read (mesh/refinement.hpp, mesh/tet_refinement.hpp). The parent facets and cells
// always compose. The form's other statement, that every new fine vertex halves an edge of the
// coarse mesh, holds for a vertex unless it halves an edge that a skipped level made; such a
// vertex gets no parents (midpoint_edge −1 in 2D, midpoint_ends {−1, −1} in 3D), and maps with
// one are partial: not for cartesian_prolongation (the transfer between the levels is then the
// product of the levels' transfers).

#include "mesh/refinement.hpp"
#include "mesh/tet_refinement.hpp"

namespace fosls {

/// The maps coarse → fine from `first` (coarse → middle) and `second` (middle → fine).
RefinementMaps compose_refinement_maps(const Mesh& middle, const RefinementMaps& first,
                                       const RefinementMaps& second);
TetRefinementMaps compose_refinement_maps(const TetMesh& middle, const TetRefinementMaps& first,
                                          const TetRefinementMaps& second);

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
