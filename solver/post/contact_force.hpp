#pragma once
// The contact pressure of a facet and the contact force, in 2D and 3D, from a solution in the
// space's rotated, scaled coordinates (docs/result-format.md). RT0's normal flux is constant on
// a facet, so a facet's pressure is its S_n over its measure.

#include <vector>

#include "core/box_qp.hpp"
#include "fem/fosls_space.hpp"

namespace fosls {

/// The contact pressure p = −σ_nn of contact facet f in physical units (+0.0, not −0.0, where
/// S_n = 0); `stress_scale` is AssembledProblem::stress_scale.
template <int dim>
double facet_pressure(const FoslsSpace<dim>& space, const Vector& x_full, double stress_scale,
                      int f) {
  return 0.0 - x_full[space.sigma_dof(f, 0)] * stress_scale / space.mesh().facet_measure(f);
}

/// facet_pressure of every facet, zero off the contact boundary.
template <int dim>
std::vector<double> contact_pressure(const FoslsSpace<dim>& space, const Vector& x_full,
                                     double stress_scale);

/// ∫_Γ_C σn over the contact facets in physical units: the obstacle's force on the body (the
/// rows' fluxes through each facet, its frame turned back to Cartesian).
template <int dim>
Vec<dim> contact_force(const FoslsSpace<dim>& space, const Vector& x_full, double stress_scale);

}  // namespace fosls
