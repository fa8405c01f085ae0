#pragma once
// The truncated level hierarchy of the multilevel cycle (docs/method.md §4.2): for a truncated
// set of the finest level (the active set after pre-smoothing; TNNMG's frozen set), the
// truncated prolongations P̃_j, the truncated sets of the coarser levels and their Galerkin
// matrices P̃ᵀAP̃ — rebuilt only when the set changes. Without truncation the levels are the
// Galerkin chain's untruncated matrices, not copied.

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "core/box_qp.hpp"
#include "core/level_hierarchy.hpp"
#include "solvers/galerkin_chain.hpp"
#include "solvers/reversible_edits.hpp"
#include "solvers/truncated_prolongation.hpp"

namespace fosls {

class TruncatedHierarchy {
 public:
  /// The hierarchy edits the chain's second-finest matrix in place while truncating and
  /// restores it exactly whenever the truncation changes and when it is destroyed: no one else
  /// may use that matrix while it lives. Nothing is built before the first set_truncation.
  TruncatedHierarchy(const BoxQp& qp, const LevelHierarchy& hierarchy,
                     std::shared_ptr<GalerkinChain> chain);
  ~TruncatedHierarchy();
  TruncatedHierarchy(const TruncatedHierarchy&) = delete;
  TruncatedHierarchy& operator=(const TruncatedHierarchy&) = delete;

  /// Builds the levels for the fine truncated set `truncated` unless they were built for it;
  /// returns whether it built. `level_built(j)` is called for every level j from the
  /// second-finest down to level 1, once its matrix and P̃_j are formed and before level j−1
  /// is formed from them (the cycle builds the level's smoothers there). When it throws
  /// IndefiniteSystemError on a truncated level, the level's diagonal is shifted further and it
  /// is called once more.
  bool set_truncation(const std::vector<char>& truncated,
                      const std::function<void(int j)>& level_built);

  /// Level j's matrix (the problem's own on the finest level).
  const SparseMatrix& matrix(int j) const;
  /// P̃_j, from level j−1 to level j (j ≥ 1).
  const TruncatedProlongation& prolongation(int j) const { return prolongations_[j]; }
  /// Level j's truncated set (j ≥ 1): the fine truncated set on the finest level; on coarser
  /// levels the S_n whose fine descendants are all truncated.
  const std::vector<char>& truncated(int j) const { return level_truncated_[j]; }
  /// The weights of the fine S_n of each link of level j in P̃_j (project_defect).
  const std::vector<std::array<double, 2>>& sn_weights(int j) const { return sn_weights_[j]; }

 private:
  struct LevelMatrix {
    /// The chain's untruncated matrix while nothing is truncated, else `truncated` (or, on the
    /// second-finest level, the chain's matrix edited in place).
    SparseMatrix* A = nullptr;
    SparseMatrix truncated;
  };

  /// P̃_j from level j's truncated set and matrix; sets level j−1's truncated set.
  void truncate_level(int j);
  /// The flux moves of P̃_j at the links of level j (see truncate_level) and level j−1's
  /// truncated S_n; updates sn_weights_[j].
  SparseMatrix flux_moves(int j, std::vector<char>& coarse_truncated);
  /// Level j's matrix for the current truncated set.
  void form_level(int j, bool truncating);
  /// The truncated matrix of the second-finest level, in the chain's storage when the
  /// correction stays within its pattern, else in its own.
  void truncate_second_finest();
  /// A larger diagonal shift of level j (kRetryCoarseShift), saved when in the chain.
  void shift_diagonal(int j);
  /// The chain's A_j, formed from A_{j+1} first if it was not (GalerkinChain).
  SparseMatrix& chain_matrix(int j);

  const BoxQp& qp_;
  const LevelHierarchy& hierarchy_;
  std::shared_ptr<GalerkinChain> chain_;
  /// Edits of the chain's second-finest matrix made by the truncation (restored on change).
  std::unique_ptr<ReversibleEdits> top_edits_;
  std::vector<LevelMatrix> levels_;
  std::vector<char> truncated_;  ///< the fine truncated set the levels were built for
  bool built_ = false;
  /// Per level j ≥ 1 (index j).
  std::vector<std::vector<char>> level_truncated_;
  std::vector<TruncatedProlongation> prolongations_;
  std::vector<std::vector<std::array<double, 2>>> sn_weights_;
};

}  // namespace fosls
