#pragma once
// A fine vertex of refinement maps composed across skipped levels (mesh/composed_refinement.hpp)
// as the P1 combination of coarse vertices: what the coarse contact links need to bound a
// coarse U_n by the fine U_n of every vertex it interpolates to (assembly/contact_links.hpp),
// also where the vertex halves an edge that a skipped level made.

#include <array>

namespace fosls {

/// At most three coarse vertices — those of the coarse facet or triangle the fine vertex lies
/// in — and their P1 weights (dyadic, exact), −1 and 0 where unused; none at all where a fine
/// vertex lies inside a coarse tetrahedron (four vertices: never on the boundary).
struct CoarseVertexWeights {
  std::array<int, 3> vertex = {-1, -1, -1};
  std::array<double, 3> weight = {0.0, 0.0, 0.0};
  bool known() const { return vertex[0] >= 0; }
};

}  // namespace fosls
