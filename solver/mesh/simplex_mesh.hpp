#pragma once
// The dimension as a template parameter (docs/architecture.md, "Three dimensions"): the mesh,
// its refinement maps and its hierarchy of dimension dim, and a point of R^dim. The meshes stay
// two classes — Mesh (triangles, circular arcs, bisection) and TetMesh (tetrahedra, sphere
// groups) — because their boundary representation, orientation conventions, refinement rules
// and readers are where the geometry really differs; both speak one vocabulary (num_cells,
// cell_facet, facet_normal, …), which is all that the layers written once for both see.

#include <Eigen/Core>
#include <type_traits>
#include <utility>

#include "mesh/mesh.hpp"
#include "mesh/refinement.hpp"
#include "mesh/tet_mesh.hpp"
#include "mesh/tet_refinement.hpp"

namespace fosls {

/// A point or vector of R^dim: Point for 2, Point3 for 3.
template <int dim>
using Vec = Eigen::Matrix<double, dim, 1>;

/// A dim × dim matrix (contact frames, stresses).
template <int dim>
using Mat = Eigen::Matrix<double, dim, dim>;

/// Mesh for 2, TetMesh for 3.
template <int dim>
using SimplexMesh = std::conditional_t<dim == 2, Mesh, TetMesh>;

/// The parent/child relation of one refinement: RefinementMaps for 2, TetRefinementMaps for 3.
template <int dim>
using SimplexRefinementMaps = std::conditional_t<dim == 2, RefinementMaps, TetRefinementMaps>;

/// The nested meshes T_1 ⊂ … ⊂ T_J: MeshHierarchy for 2, TetHierarchy for 3.
template <int dim>
using SimplexHierarchy = std::conditional_t<dim == 2, MeshHierarchy, TetHierarchy>;

/// The coarse mesh and its uniform refinements, in either dimension.
inline MeshHierarchy build_uniform_hierarchy(Mesh coarse, int refinements) {
  return build_mesh_hierarchy(std::move(coarse), refinements);
}
inline TetHierarchy build_uniform_hierarchy(TetMesh coarse, int refinements) {
  return build_tet_hierarchy(std::move(coarse), refinements);
}

}  // namespace fosls
