#pragma once
// The change of the second-finest Galerkin matrix under truncation (docs/method.md §4.2),
// formed without redoing the fine-level product for every new truncated set.

#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

/// P̃ᵀAP̃ − PᵀAP for P̃ = P without the rows i with truncated[i], plus `moves` (the flux moves of
/// the truncated prolongation): small, the contact boundary's couplings. A is symmetric.
void truncation_correction(const SparseMatrix& A, const SparseMatrix& P,
                           const std::vector<char>& truncated, const SparseMatrix& moves,
                           SparseMatrix& out);

}  // namespace fosls
