#pragma once
// The block of the contact-strip smoother (docs/method.md §4.1): the free DOFs of the cells
// near the contact boundary, for every space (P1–RT0 in 2D and 3D, order 2).

#include <vector>

namespace fosls {

/// Free DOFs of the cells within `layers` layers of the contact boundary, sorted; empty without
/// contact. A Space has mesh() (cells and facets), is_contact_facet, cell_dofs and free_index
/// (FoslsSpace<2>, FoslsSpace<3>, P2Rt1Space). In 2D two layers make the iteration counts
/// level-independent on the square benchmark and one does not (docs/performance.md,
/// "Measurements behind choices in the code"); in 3D two layers make a slab whose exact solve
/// dominated the solve, one is 2.6 times faster for 5 more iterations (docs/performance.md,
/// "3D"): Discretization<dim>::kStripLayers.
template <class Space>
std::vector<int> contact_strip(const Space& space, int layers);

}  // namespace fosls
