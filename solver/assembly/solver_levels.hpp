#pragma once
// The mesh levels that the multilevel solvers cycle on (docs/method.md §4): on a hierarchy of
// bisection steps each level holds 55–60 % of the next one's unknowns, so a cycle visits twice
// as many levels as the unknowns need, and its coarse rebuilds form and factorise every one of
// them. Keeping only levels a factor apart gives the cycle about a uniform hierarchy's spacing:
// the transfer between two kept levels is the product of the levels' transfers between them,
// and their contact links and local smoothing sets come from the composed refinement maps
// (mesh/composed_refinement.hpp). A uniform hierarchy (4 or 8 times the unknowns per level)
// keeps every level.

#include <functional>
#include <vector>

#include "mesh/simplex_mesh.hpp"

namespace fosls {

/// The largest share of the next kept level's unknowns that a kept level may have while a
/// coarser level can still be reached by composed maps: a level at most half the next one
/// (docs/performance.md, "The solver levels a factor apart" and "The contact zone's levels
/// skipped too").
constexpr double kMaxSolverLevelShare = 0.5;

/// The share for the 2D accuracy loop's adaptive levels: about a uniform hierarchy's spacing
/// (a uniform 2D level holds about 25 % of the next one's unknowns). A cycle then visits about
/// 1.3 times the finest level's unknowns instead of about twice, and its coarse rebuilds form
/// and factorise that much less (docs/performance.md, "The accuracy loop's solver levels a
/// uniform factor apart"). Uniform accuracy levels, the `adaptivity` loop and 3D keep
/// kMaxSolverLevelShare: not measured with it.
constexpr double kAccuracySolverLevelShare = 0.3;

template <int dim>
struct SolverLevels {
  std::vector<int> mesh_levels;  ///< kept mesh levels, coarsest first
  /// maps[k]: from mesh level mesh_levels[k − 1] to mesh_levels[k] (maps[0] empty).
  std::vector<SimplexRefinementMaps<dim>> maps;
};

/// From the finest level down, the next kept level is the finest one below with at most
/// `max_share` of its unknowns: the contact links relate a coarse contact facet to any number of
/// fine children and a coarse U_n to every fine contact vertex it interpolates to (the composed
/// maps' vertex weights), so the contact zone's levels are skipped too. (A composition would stop
/// at a vertex on the contact boundary without coarse weights; none has any.) `unknowns[j]`:
/// level j's free DOFs; `on_contact(j, v)`: vertex v of level j lies on the contact boundary;
/// levels below `coarsest` are not used.
template <int dim>
SolverLevels<dim> skip_close_levels(const SimplexHierarchy<dim>& meshes,
                                    const std::vector<long long>& unknowns,
                                    const std::function<bool(int, int)>& on_contact, int coarsest,
                                    double max_share = kMaxSolverLevelShare);

}  // namespace fosls
