#pragma once
// The refinement steps of the adaptive and accuracy loops (strategy/level_loop.hpp) under
// one set of names for both dimensions: newest-vertex bisection of triangles (bisection.hpp) and of
// tetrahedra (tet_bisection.hpp), and the uniform refinement of either. The algorithms stay in
// their own files because the geometry differs; the loop that calls them is written once.

#include <vector>

#include "mesh/bisection.hpp"
#include "mesh/simplex_mesh.hpp"
#include "mesh/tet_bisection.hpp"

namespace fosls {

/// BisectionState for 2, TetBisectionState for 3.
template <int dim>
using SimplexBisectionState = std::conditional_t<dim == 2, BisectionState, TetBisectionState>;

/// Bisections in one uniform refinement: a red triangle is two (area / 4), a red tetrahedron
/// three (volume / 8); the unit of SimplexBisectionState::generation.
template <int dim>
constexpr int kBisectionsPerUniformRefinement = dim;

/// The initial marking of a mesh, every cell `generation` bisections from its coarse ancestor.
inline BisectionState initial_bisection_state(const Mesh& mesh, int generation) {
  return longest_edge_state(mesh, generation);
}
inline TetBisectionState initial_bisection_state(const TetMesh& mesh, int generation) {
  return initial_tet_bisection_state(mesh, generation);
}

/// One adaptive step: the marked cells of the finest mesh bisected with closure, appended as
/// new finest level(s). Returns the number of levels appended (2D: always 1; 3D: more when the
/// closure needs vertices off the finest mesh's edges, tet_bisection.hpp).
inline int bisect_finest_level(MeshHierarchy& hierarchy, BisectionState& state,
                               const std::vector<int>& marked) {
  refine_finest_level(hierarchy, state, marked);
  return 1;
}
inline int bisect_finest_level(TetHierarchy& hierarchy, TetBisectionState& state,
                               const std::vector<int>& marked) {
  return refine_finest_tet_level(hierarchy, state, marked);
}

/// The red refinement of a mesh: Refinement for a Mesh, TetRefinement for a TetMesh.
inline Refinement refine_all_cells(const Mesh& mesh) { return refine_uniformly(mesh); }
inline TetRefinement refine_all_cells(const TetMesh& mesh) { return refine_tets_uniformly(mesh); }

/// All DOFs of the lowest-order space on a mesh (fixed ones included): d per vertex (u) and d
/// per facet (the stress rows' normal fluxes); the measure of the loops' max_dofs.
inline long long lowest_order_dofs(const Mesh& mesh) {
  return 2LL * (mesh.num_vertices() + mesh.num_edges());
}
inline long long lowest_order_dofs(const TetMesh& mesh) {
  return 3LL * (mesh.num_vertices() + mesh.num_faces());
}

}  // namespace fosls
