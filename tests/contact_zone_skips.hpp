#pragma once
// How many contact links of a solver hierarchy relate levels across a skipped refinement of the
// contact zone (issue 48): a U_n point with weights other than ½, ½ (a chain of midpoints, or in
// 3D a vertex inside a coarse face), or an S_n link among partners (a coarse contact edge or face
// with more fine children than one uniform refinement gives: two in 2D, four in 3D).
#include <cstddef>

#include "core/level_hierarchy.hpp"

namespace fosls::testing {

inline int contact_zone_skips(const LevelHierarchy& h, int dim) {
  // One uniform refinement halves a 2D edge (one pair of children) and quarters a 3D face (two).
  const std::size_t pairs_of_one_refinement = dim == 2 ? 1 : 2;
  int skips = 0;
  for (const Level& level : h.levels)
    for (const ContactLink& l : level.links) {
      const bool chain = l.fine_un_mid >= 0 && (l.un_weight[0] != 0.5 || l.un_weight[1] != 0.5);
      const bool more_children =
          l.coarse_sn >= 0 && l.partners.size() + 1 > pairs_of_one_refinement;
      skips += chain || more_children;
    }
  return skips;
}

}  // namespace fosls::testing
