#pragma once
// The bisection rule of Arnold–Mukherjee–Pouly's marked tetrahedra (tet_bisection.hpp) on global
// vertex numbers: one tetrahedron into two, with the children's marking.

#include <array>

#include "mesh/tet_bisection.hpp"

namespace fosls {

/// A marked tetrahedron in global vertex numbers: v[0] v[1] its refinement edge; peak[0] (peak[1])
/// the vertex of the face opposite v[0] (v[1]) that its marked edge leaves out.
struct MarkedTet {
  std::array<int, 4> v;
  std::array<int, 2> peak;
  bool flagged = false;
  int depth = 0;  ///< bisections since the step's input tetrahedron

  /// The marked edges of the two faces without the refinement edge lie in one plane with it.
  bool planar() const { return peak[0] == peak[1]; }
};

/// The input tetrahedron `vertices` (its mesh order) with its label.
MarkedTet marked_tet(const std::array<int, 4>& vertices, const TetLabel& label);

/// The label of `t` for the vertex order t.v.
TetLabel label_of(const MarkedTet& t);

/// The two children of `t` when its refinement edge is cut at the new vertex `midpoint`: the one
/// with t.v[0] first, then the one with t.v[1].
std::array<MarkedTet, 2> bisect(const MarkedTet& t, int midpoint);

/// Whether `label` is a marking of a tetrahedron: order a permutation, each peak on its face.
bool valid_label(const TetLabel& label);

}  // namespace fosls
