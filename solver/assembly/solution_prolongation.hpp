#pragma once
// Carrying a solution from one level to the next finer one: the start of the next solve of an
// adaptive loop.

#include "assembly/discretization.hpp"

namespace fosls {

/// The free DOFs of the finest level of `disc` for the solution whose full DOF vector (fixed
/// values included; rotated contact coordinates, scaled stresses: FoslsAssembler::full_vector)
/// on level `from_level` (−1: the second-finest; a 3D bisection step may append several levels)
/// is `full_coarse`, carried level by level by the level transfer
/// (fem/transfer.hpp: P1 interpolation for u, the RT0 embedding for σ). Bounds are not imposed
/// here: the solve loop projects its initial iterate onto them (a midpoint's interpolated U_n
/// can exceed a curved gap). Throws std::invalid_argument when `disc` has no level below the
/// finest or full_coarse has the wrong size.
template <int dim>
Vector prolongate_to_finest(const Discretization<dim>& disc, const Vector& full_coarse,
                            int from_level = -1);

}  // namespace fosls
