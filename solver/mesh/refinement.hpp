#pragma once
// Uniform red refinement and the nested level hierarchy T_1 ⊂ … ⊂ T_J.

#include <vector>

#include "mesh/mesh.hpp"

namespace fosls {

/// Parent/child relation between a coarse mesh and its red refinement.
///
/// Fine vertex v < num_coarse_vertices is coarse vertex v; fine vertex num_coarse_vertices + e
/// is the midpoint of coarse edge e (moved onto the boundary curve where the edge is curved).
struct RefinementMaps {
  int num_coarse_vertices = 0;
  /// For each fine edge: the coarse edge it halves (-1 if interior to a coarse triangle).
  std::vector<int> parent_edge;
  /// For each fine edge inside a coarse triangle: that triangle (-1 otherwise).
  std::vector<int> parent_triangle;
  /// For a fine half edge: +1 when its normal agrees with the coarse edge's normal.
  std::vector<signed char> parent_sign;
};

/// One red refinement: every triangle split into four by its edge midpoints.
struct Refinement {
  Mesh fine;
  RefinementMaps maps;
};

Refinement refine_uniformly(const Mesh& coarse);

/// Meshes of all levels, coarsest first, and maps[j] relating level j-1 to level j (maps[0]
/// is empty).
struct MeshHierarchy {
  std::vector<Mesh> meshes;
  std::vector<RefinementMaps> maps;
  int num_levels() const { return static_cast<int>(meshes.size()); }
  const Mesh& finest() const { return meshes.back(); }
};

MeshHierarchy build_mesh_hierarchy(Mesh coarse, int refinements);

}  // namespace fosls
