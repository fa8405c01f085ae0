#pragma once
// Conforming local refinement of tetrahedral meshes by newest-vertex bisection with closure
// (docs/method.md §11): the 3D counterpart of bisection.hpp, for any conforming tetrahedral mesh
// (the Kuhn box, the half and quarter ball, meshes from gmsh).
//
// The algorithm is Arnold–Mukherjee–Pouly's marked tetrahedra (SIAM J. Sci. Comput. 22, 2000),
// chosen because it needs no condition on the coarse mesh: Maubach's and Stevenson's labellings
// are conforming only on meshes that satisfy a matching condition, which a gmsh mesh does not in
// general. Each tetrahedron carries a refinement edge and, on each of its faces, a marked edge
// (the face's newest vertex in 2D's sense), with the refinement edge marked on both faces that
// hold it. Initially every edge is ranked by length, ties broken by its global vertex pair, and
// the marked edge of a face is its top-ranked edge and the refinement edge of a tetrahedron its
// top-ranked edge: the marking depends on the face alone, so both tetrahedra on a face agree.
//
// Bisecting T = (x0, x1, x2, x3) with refinement edge x0x1 at its midpoint m gives (x0, m, x2,
// x3) and (m, x1, x2, x3). Each child's refinement edge is the marked edge of the face it keeps
// whole from T; a half of a face of T is marked on its edge of T (opposite m, as 2D's newest
// vertex); the new face (m, x2, x3) is marked on x2x3, except in a flagged planar T (the marked
// edges of the two faces without x0x1 meet in an apex a of the plane x0x1a), where it is marked on
// m a. Children of an unflagged planar T are flagged. The types then cycle mixed → planar →
// flagged planar → mixed from the first generation on, which is Maubach's bisection with tags
// 3, 2, 1 (checked on Kuhn's tetrahedron, which is mixed under the initial marking, step by
// step): the descendants of a tetrahedron fall into finitely many similarity classes, so the
// shape stays bounded below (the Kuhn box's descendants stay in three classes, tested).
//
// One step: the marked tetrahedra's refinement edges are marked, and the closure marks the
// refinement edge of every tetrahedron of the would-be fine mesh that holds a marked edge, until
// none does. Only edges of the input mesh are ever marked, so every new vertex is the midpoint of
// an input edge (maps.midpoint_ends keeps its meaning, prolongation is P1 interpolation) and the
// fine mesh is conforming: on every face both sides cut by 2D bisection of the same marked edges.
// A tetrahedron is bisected at most three times in one step; its refinement edges are input edges
// at all three depths unless it starts flagged planar, whose grandchild on the new face would be
// cut at m a. A step whose closure needs that (on adapted gmsh meshes, where the generations
// around an edge differ widely: 3 of 8 random steps in tests/unit/tet_bisection_test.cpp) is
// refused by refine_tets_by_bisection; refine_tets_by_bisection_in_part does the largest
// conforming part of it and refine_finest_tet_level the rest in further levels.

#include <array>
#include <vector>

#include "mesh/tet_refinement.hpp"

namespace fosls {

/// A marked tetrahedron in the local vertex indices (0–3) of its mesh's tetrahedron.
struct TetLabel {
  /// order[0], order[1]: the ends of the refinement edge; order[2], order[3]: the other two.
  std::array<signed char, 4> order = {0, 1, 2, 3};
  /// The marked edges of the two faces without the refinement edge, each as the face's vertex
  /// opposite it: peak[0] on the face opposite order[0], peak[1] on the face opposite order[1].
  std::array<signed char, 2> peak = {2, 2};
  /// Set on the children of an unflagged planar tetrahedron (peak[0] == peak[1]).
  bool flagged = false;
};

/// What bisection needs to know about each tetrahedron of a mesh.
struct TetBisectionState {
  std::vector<TetLabel> labels;
  /// Number of bisections from each tetrahedron's coarse ancestor (volume / 2^generation).
  std::vector<int> generation;
};

/// The initial marking: every edge ranked by its length, ties by its global vertex pair; each
/// face's marked edge and each tetrahedron's refinement edge its top-ranked one; nothing flagged.
TetBisectionState initial_tet_bisection_state(const TetMesh& mesh, int generation = 0);

using TetBisection = BisectionStep<TetMesh, TetRefinementMaps, TetBisectionState>;

/// The deepest bisection of one tetrahedron in one step (all six edges halved, volume / 8).
constexpr int kMaxBisectionsPerStep = 3;

/// Bisects each marked tetrahedron (indices into `mesh`) as often as it is listed (at most
/// kMaxBisectionsPerStep) and the closure that keeps the mesh conforming. Fine tetrahedra are
/// ordered by their coarse parent; a kept tetrahedron keeps its vertex order; new vertices follow
/// the old ones, each the midpoint of an input edge (moved radially onto the sphere of a curved
/// boundary group it lies on). Throws std::invalid_argument for an out-of-range tetrahedron, one
/// listed too often or a state that does not belong to the mesh, and std::runtime_error when the
/// closure needs a vertex off the input edges or a midpoint moved onto a sphere inverts a
/// tetrahedron.
TetBisection refine_tets_by_bisection(const TetMesh& mesh, const TetBisectionState& state,
                                      const std::vector<int>& marked);

/// As refine_tets_by_bisection, but when the closure needs a vertex off the input edges it does
/// the largest conforming part of the step whose vertices are midpoints of input edges, and
/// `remaining` lists the fine tetrahedra still to be bisected for the marks (each as often as
/// still wanted), for the next step from the fine mesh. Empty when the whole step was done.
TetBisection refine_tets_by_bisection_in_part(const TetMesh& mesh, const TetBisectionState& state,
                                              const std::vector<int>& marked,
                                              std::vector<int>& remaining);

/// One adaptive step on a nested hierarchy: bisects the marked tetrahedra of its finest mesh
/// (with closure) and appends the result as new finest level, or as a few levels when the step
/// needs vertices off the edges of the finest mesh (each level nested in the one below, its new
/// vertices midpoints of that level's edges); `state` belongs to the finest mesh before the call
/// and to the new one after it (nothing marked: one level, the same mesh). Returns the number of
/// levels appended.
int refine_finest_tet_level(TetHierarchy& hierarchy, TetBisectionState& state,
                            const std::vector<int>& marked);

}  // namespace fosls
