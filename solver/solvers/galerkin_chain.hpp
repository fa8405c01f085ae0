#pragma once
// The untruncated Galerkin matrices of the coarser levels, shared by the nested iteration, the
// cycles of every level and the definiteness check.

#include <limits>
#include <vector>

#include "core/box_qp.hpp"
#include "core/level_hierarchy.hpp"

namespace fosls {

/// The untruncated Galerkin matrices A_j = P_{j+1}ᵀ A_{j+1} P_{j+1} of every coarser level,
/// computed once per solve. The products A_j P_j are not kept: the truncation corrections need
/// only the few rows of A P at the contact boundary, recomputed from A and P per rebuild (kept,
/// the finest A P was the largest matrix of a solve: docs/performance.md).
struct GalerkinChain {
  /// A_0 … A_{J−1} (A_J is the problem's own matrix); an empty (0 × 0) matrix is one not formed
  /// yet, below those formed (TruncatedHierarchy::chain_matrix forms it when a level needs it).
  std::vector<SparseMatrix> matrices;
};

/// The chain, formed down to `levels` levels below the finest (all by default). A cycle that
/// truncates from its first iteration on, as every contact solve from a prolongated start does,
/// uses only A_{J−1}: its coarser levels are products of truncated matrices instead.
GalerkinChain galerkin_chain(const SparseMatrix& A, const LevelHierarchy& hierarchy,
                             int levels = std::numeric_limits<int>::max());

/// Positive definiteness, checked by CHOLMOD on the finest level of the Galerkin chain with at
/// most `max_dofs` DOFs: PᵀAP indefinite implies A indefinite, and the limit of c3 barely moves
/// with h (docs/method.md §2.1), so a level of ≤ 5·10⁴ DOFs decides at a small fraction of the
/// cost of factorising the finest matrix; weights within ≈ 10 % of the limit may pass. mmg and
/// tnnmg run this check first (in an adaptive case on its first step:
/// SolverOptions::check_definiteness); pdas learns it from its own factorisation.
bool chain_is_definite(const SparseMatrix& A, const GalerkinChain& chain, int max_dofs = 50000);

}  // namespace fosls
