#pragma once
// Uniform refinement of tetrahedral meshes (each tetrahedron into eight, Bey's red refinement)
// and the nested hierarchy T_1 ⊂ … ⊂ T_J of the 3D multilevel method (docs/method.md §11);
// the built-in box mesh.

#include <functional>
#include <vector>

#include "mesh/coarse_vertex_weights.hpp"
#include "mesh/nested_meshes.hpp"
#include "mesh/tet_mesh.hpp"

namespace fosls {

/// Parent/child relation between a tetrahedral mesh and its red refinement. Fine vertex
/// v < num_coarse_vertices is coarse vertex v; fine vertex num_coarse_vertices + k is the
/// midpoint of the coarse edge midpoint_ends[k].
struct TetRefinementMaps {
  int num_coarse_vertices = 0;
  std::vector<std::array<int, 2>> midpoint_ends;
  /// For each fine face inside a coarse face (a quarter of it under red refinement, a half, a
  /// quarter … or all of it under bisection): that face; −1 otherwise.
  std::vector<int> parent_face;
  /// For each fine face inside a coarse face: the fraction of the coarse face's area it covers, a
  /// power of two (exact: computed from the vertices' barycentric coordinates); 0 otherwise.
  std::vector<double> parent_face_share;
  /// For each fine face inside a coarse tetrahedron: that tetrahedron; −1 otherwise.
  std::vector<int> parent_tet_of_face;
  /// For each fine tetrahedron: the coarse one that contains it.
  std::vector<int> tet_parent;
  /// Maps composed across skipped levels only (empty otherwise): each new fine vertex's P1
  /// weights over the coarse vertices (mesh/composed_refinement.hpp).
  std::vector<CoarseVertexWeights> composed_weights;

  // The vocabulary RefinementMaps shares (mesh/simplex_mesh.hpp).
  int parent_facet(int f) const { return parent_face[f]; }
  int parent_cell_of_facet(int f) const { return parent_tet_of_face[f]; }
  int cell_parent(int t) const { return tet_parent[t]; }
  int num_midpoints() const { return static_cast<int>(midpoint_ends.size()); }
  const std::array<int, 2>& midpoint_parents(const TetMesh&, int k) const {
    return midpoint_ends[k];
  }
};

using TetRefinement = RefinementStep<TetMesh, TetRefinementMaps>;

/// Every tetrahedron (x0, x1, x2, x3) into its four corner tetrahedra and four from the inner
/// octahedron, cut along the diagonal x02–x13 (Bey 1995: the vertex order of the children keeps
/// the shapes of the refinements of a tetrahedron in finitely many classes).
TetRefinement refine_tets_uniformly(const TetMesh& coarse);

/// Fills maps.parent_face, parent_face_share and parent_tet_of_face of a refinement whose fine
/// vertices are coarse vertices and midpoints of coarse edges (maps.midpoint_ends and tet_parent
/// set): a fine face whose vertices all lie between the three vertices of a coarse face is in it.
void map_fine_faces(const TetMesh& coarse, const TetMesh& fine, TetRefinementMaps& maps);

using TetHierarchy = NestedMeshes<TetMesh, TetRefinementMaps>;

TetHierarchy build_tet_hierarchy(TetMesh coarse, int refinements);

/// One cube's six Kuhn tetrahedra, appended to `tets`: the paths from grid point `start` to the
/// opposite corner, one axis at a time, each axis a stepping by step[a] (±1); `id` numbers the
/// grid points. Each tetrahedron's vertices are in path order (what Bey's refinement keeps).
void append_kuhn_cube(const std::array<int, 3>& start, const std::array<int, 3>& step,
                      const std::function<int(int, int, int)>& id,
                      std::vector<std::array<int, 4>>& tets);

/// The box [0, lx] × [0, ly] × [0, lz] in n_x × n_y × n_z cubes of six Kuhn tetrahedra each (a
/// conforming mesh whose red refinements stay in three shape classes); boundary groups left,
/// right (x = 0, lx), front, back (y), bottom, top (z).
TetMesh make_box(const std::array<int, 3>& cells, const Point3& lengths = Point3(1, 1, 1));

}  // namespace fosls
