#pragma once
// The contact links between a level and the one below (docs/method.md §4.3, §11), in 2D and 3D:
// how the coarse contact DOFs are related to the fine ones, for the projections that carry the
// defect obstacle to the coarse level (core/level_hierarchy.hpp, ContactLink).

#include <vector>

#include "core/level_hierarchy.hpp"
#include "fem/fosls_space.hpp"

namespace fosls {

/// One link per coarse contact edge for U_n (its ends and the fine midpoint, interpolated with
/// ½, ½; a kept edge has no midpoint), one per other fine contact vertex of a composed refinement
/// (across skipped levels: a chain of midpoints along a coarse edge, a vertex inside a coarse
/// face, with its coarse vertices' P1 weights), and the fine facets inside each coarse contact
/// facet in pairs for S_n (a facet's two halves in 2D, a face's four quarters in two pairs in 3D,
/// any number across skipped levels), each with its weight in `prolongation` and the flux moves
/// that keep a coarse S_n's flux when one fine S_n of the pair is truncated. Where a facet has
/// more than one pair, the pairs are each other's partners, so that a pair whose both members
/// are truncated moves its share onto another. In 2D a coarse contact edge is a facet, and its
/// U_n link and its first S_n pair are one link.
template <int dim>
std::vector<ContactLink> contact_links(const FoslsSpace<dim>& coarse, const FoslsSpace<dim>& fine,
                                       const SimplexRefinementMaps<dim>& maps,
                                       const SparseMatrix& prolongation);

}  // namespace fosls
