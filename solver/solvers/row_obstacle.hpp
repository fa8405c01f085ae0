#pragma once
// Coarse obstacles for DOFs with bounds of any kind (the frictional contact DOFs, docs/method.md
// §8), from the rows of the truncated prolongation: a fine DOF i with room [l_i, u_i] (l ≤ 0 ≤
// u) for its correction, reached by the coarse DOFs J of its row with weights P_iJ, stays
// within it when each P_iJ c_J lies in |P_iJ| [l_i, u_i] / Σ_J |P_iJ|. Each coarse DOF so
// bounded carries its bounds on to the next coarser level in the same way. Coarser than the
// contact links' projections (coarse_obstacle.hpp), but valid for every row, so a coarse
// correction never has to be shortened for these DOFs.

#include <vector>

#include "core/box_qp.hpp"
#include "solvers/truncated_prolongation.hpp"

namespace fosls {

/// Intersects [coarse_lo, coarse_hi] with the bounds the rows of P̃ marked in `rows` (and not
/// `truncated`) impose for the iterate c within [lo, hi]; marks the coarse DOFs bounded so in
/// `coarse_rows`.
void project_row_obstacles(const TruncatedProlongation& p, const std::vector<char>& rows,
                           const std::vector<char>& truncated, const Vector& c, const Vector& lo,
                           const Vector& hi, Vector& coarse_lo, Vector& coarse_hi,
                           std::vector<char>& coarse_rows);

}  // namespace fosls
