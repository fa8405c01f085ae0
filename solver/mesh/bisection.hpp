#pragma once
// Conforming newest-vertex bisection (NVB) with closure: local refinement that keeps the mesh
// conforming and shape regular and gives a nested sequence of meshes.
//
// Every triangle has a refinement edge, the edge opposite its newest vertex. Bisecting a
// triangle (p0, p1, p2) with newest vertex p0 joins the midpoint m of its refinement edge
// (p1, p2) to p0; the children are (m, p0, p1) and (m, p2, p0), each with m as its newest
// vertex, so their refinement edges are the parent's other two edges. One refinement step:
//   1. mark the refinement edges of the marked triangles;
//   2. closure: a triangle with a marked edge gets its refinement edge marked as well, until
//      nothing changes (the marked edges then leave no hanging vertex);
//   3. bisect each triangle whose refinement edge is marked, then each child whose refinement
//      edge (an edge of the parent) is marked: a triangle is split into 1, 2, 3 or 4 pieces.
// All descendants of a coarse triangle are similar to one of at most four shapes per coarse
// triangle, so the minimum angle stays bounded below; the refinement edges of the coarse mesh
// are its longest edges. Boundary midpoints on arcs are moved onto the arc, as in uniform
// refinement, and boundary groups are inherited.

#include <vector>

#include "mesh/refinement.hpp"

namespace fosls {

/// What newest-vertex bisection needs to know about each triangle of a mesh.
struct BisectionState {
  /// Local index (0, 1, 2) of each triangle's newest vertex; the refinement edge is the
  /// triangle's edge of the same local index (the one opposite the vertex).
  std::vector<signed char> newest;
  /// Number of bisections that separate each triangle from its coarse-mesh ancestor (its area
  /// is the ancestor's divided by 2^generation; a red refinement counts as two).
  std::vector<int> generation;
};

/// The initial state of a mesh: each triangle's longest edge (ties broken by the edge index)
/// is its refinement edge; all generations equal `generation`.
BisectionState longest_edge_state(const Mesh& mesh, int generation = 0);

using Bisection = BisectionStep<Mesh, RefinementMaps, BisectionState>;

/// Refines the marked triangles (indices into `mesh`, repetitions allowed) and the closure
/// that keeps the mesh conforming. Fine triangles are ordered by their coarse parent; a kept
/// triangle keeps its vertex order; new vertices follow the old ones. Throws
/// std::invalid_argument for an out-of-range triangle or a state of the wrong size, and
/// std::runtime_error when moving a midpoint onto a curve inverts a triangle.
Bisection refine_by_bisection(const Mesh& mesh, const BisectionState& state,
                              const std::vector<int>& marked);

/// One adaptive step on a nested hierarchy: bisects the marked triangles of its finest mesh
/// (with closure) and appends the result as a new finest level; `state` belongs to the finest
/// mesh before the call and to the new one after it.
void refine_finest_level(MeshHierarchy& hierarchy, BisectionState& state,
                         const std::vector<int>& marked);

}  // namespace fosls
