#pragma once
// Uniform red refinement and the nested level hierarchy T_1 ⊂ … ⊂ T_J.

#include <vector>

#include "mesh/coarse_vertex_weights.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nested_meshes.hpp"

namespace fosls {

/// Parent/child relation between a coarse mesh and a refinement of it in which every coarse
/// edge is either kept or halved and every fine triangle lies in one coarse triangle (a red
/// refinement, or one step of newest-vertex bisection).
///
/// Fine vertex v < num_coarse_vertices is coarse vertex v; fine vertex num_coarse_vertices + k
/// is the midpoint of coarse edge midpoint_edge[k] (moved onto the boundary curve where the
/// edge is curved).
struct RefinementMaps {
  int num_coarse_vertices = 0;
  /// For each new fine vertex: the coarse edge it halves.
  std::vector<int> midpoint_edge;
  /// For each fine edge along a coarse edge (one of its halves, or the whole edge when it was
  /// kept): that coarse edge; -1 for edges inside a coarse triangle. A kept edge is the one
  /// whose end points are both coarse vertices.
  std::vector<int> parent_edge;
  /// For each fine edge inside a coarse triangle: that triangle (-1 otherwise).
  std::vector<int> parent_triangle;
  /// For a fine edge along a coarse edge: +1 when its normal agrees with the coarse edge's.
  std::vector<signed char> parent_sign;
  /// For each fine triangle: the coarse triangle that contains it.
  std::vector<int> triangle_parent;
  /// Maps composed across skipped levels only (empty otherwise): each new fine vertex's P1
  /// weights over the coarse vertices (mesh/composed_refinement.hpp).
  std::vector<CoarseVertexWeights> composed_weights;

  // The vocabulary TetRefinementMaps shares (mesh/simplex_mesh.hpp).
  int parent_facet(int f) const { return parent_edge[f]; }
  int parent_cell_of_facet(int f) const { return parent_triangle[f]; }
  int cell_parent(int t) const { return triangle_parent[t]; }
  /// How many fine vertices are new (midpoints of coarse edges).
  int num_midpoints() const { return static_cast<int>(midpoint_edge.size()); }
  /// The coarse vertices whose midpoint new fine vertex num_coarse_vertices + k is.
  const std::array<int, 2>& midpoint_parents(const Mesh& coarse, int k) const {
    return coarse.edge(midpoint_edge[k]);
  }
};

/// One red refinement: every triangle split into four by its edge midpoints.
using Refinement = RefinementStep<Mesh, RefinementMaps>;

Refinement refine_uniformly(const Mesh& coarse);

using MeshHierarchy = NestedMeshes<Mesh, RefinementMaps>;

MeshHierarchy build_mesh_hierarchy(Mesh coarse, int refinements);

}  // namespace fosls
