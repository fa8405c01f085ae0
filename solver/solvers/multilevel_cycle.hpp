#pragma once
// The monotone multilevel cycle of docs/method.md §4 (a W-cycle by default; V and F on
// request): smoothing, truncated coarse basis, coarse obstacles by non-linear projection, exact
// coarsest solve, prolongation.
//
// Convention: a cycle works on an iterate and its residual in place. On the finest level the
// iterate is x itself (bounds = the problem's bounds); on coarser levels it is the correction
// c_j, starting at 0, with the bounds carried down from the level above.

#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "core/box_qp.hpp"
#include "core/level_hierarchy.hpp"
#include "solvers/exact_box_qp.hpp"
#include "solvers/reversible_edits.hpp"
#include "solvers/smoothers.hpp"
#include "solvers/truncated_prolongation.hpp"

namespace fosls {

enum class SmootherType { kPatch, kPoint };
/// How the obstacle of the normal displacement is carried to a coarse contact edge
/// (docs/method.md §4.3): (a) least restrictive, (b) min of end and midpoint, (c) min over the
/// edge.
enum class CoarseProjection { kA, kB, kC };
/// How often a level visits the next coarser one: V once; W twice (a W-cycle each time); F
/// an F-cycle then a V-cycle, so that level j−k is visited k+1 times instead of W's 2^k.
enum class CycleShape { kV, kW, kF };

struct MultilevelOptions {
  SmootherType smoother = SmootherType::kPatch;
  int pre_smoothing = 1;
  int post_smoothing = 1;
  CoarseProjection projection = CoarseProjection::kA;
  /// W is the default: with the vertex-patch smoother the V-cycle rate grows with the number
  /// of levels (measured, docs/performance.md), the W-cycle's does not, and in 2D it costs at
  /// most twice the fine-level work of a V-cycle.
  CycleShape cycle = CycleShape::kW;
  /// After every sweep, solve exactly on the strip of triangles along the contact boundary
  /// (StripSmoother).
  bool strip = true;
};

/// Counters for profiling and tests.
struct CycleStatistics {
  int galerkin_rebuilds = 0;
  int safeguard_reductions = 0;  ///< prolongated corrections that had to be shortened
  /// Patch smoothers whose factors had to stay in double precision (small_cholesky_factors.hpp).
  int double_precision_smoothers = 0;
  double galerkin_s = 0.0;
  double smoothing_s = 0.0;  ///< vertex-patch or pointwise sweeps
  double strip_s = 0.0;      ///< contact-strip solves
  double coarse_s = 0.0;
};

using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

/// The untruncated Galerkin matrices A_j = P_{j+1}ᵀ A_{j+1} P_{j+1} of every coarser level,
/// computed once per solve and shared by the nested iteration, the cycles of every level and
/// the definiteness check. The products A_j P_j are not kept: the truncation corrections need
/// only the few rows of A P at the contact boundary, recomputed from A and P per rebuild (kept,
/// the finest A P was the largest matrix of a solve, ≈ 1.5 × A).
struct GalerkinChain {
  /// A_0 … A_{J−1} (A_J is the problem's own matrix); an empty (0 × 0) matrix is one not formed
  /// yet, below those formed (MultilevelCycle::chain_matrix forms it when a level needs it).
  std::vector<SparseMatrix> matrices;
};
/// The chain, formed down to `levels` levels below the finest (all by default). A cycle that
/// truncates from its first iteration on, as every contact solve from a prolongated start does,
/// uses only A_{J−1}: its coarser levels are products of truncated matrices instead.
GalerkinChain galerkin_chain(const SparseMatrix& A, const LevelHierarchy& hierarchy,
                             int levels = std::numeric_limits<int>::max());

/// The coarse obstacle of docs/method.md §4.3: from the defects d ≥ 0 of the bounded DOFs of level
/// j (kNoBound where a DOF is unbounded or truncated) to upper bounds of level j−1 that keep
/// every prolongated coarse correction below d (exactly where contact normals agree between
/// the levels). `coarse_hi` must be initialised (e.g. to kNoBound); it is only lowered.
/// `sn_weights`, when given, replaces the links' prolongation weights of the fine S_n (one pair
/// per link): the truncated prolongation moves flux between the halves of a coarse edge.
void project_defect(const Level& fine_level, CoarseProjection projection, const Vector& defect,
                    Vector& coarse_hi,
                    const std::vector<std::array<double, 2>>* sn_weights = nullptr);

class MultilevelCycle {
 public:
  /// `chain` (the Galerkin matrices of these levels) is computed here when not given. The
  /// cycle edits the chain's second-finest matrix in place while truncating and restores it
  /// exactly whenever the truncation changes and when it is destroyed: no one else may use that
  /// matrix while the cycle lives.
  MultilevelCycle(const BoxQp& qp, const LevelHierarchy& hierarchy, MultilevelOptions options,
                  std::shared_ptr<GalerkinChain> chain = nullptr);
  ~MultilevelCycle();

  /// One monotone cycle (of `options.cycle`'s shape): J(x) does not increase and x stays within
  /// [lower, upper]. The truncated set is the fine active set after pre-smoothing.
  void nonlinear_cycle(Vector& x, Vector& r);

  /// One linear cycle (of `options.cycle`'s shape) for the correction c (started at 0) on the DOFs
  /// that are not `frozen`; coarse basis functions are truncated at the frozen DOFs (TNNMG).
  void linear_cycle(const std::vector<char>& frozen, Vector& c, Vector& r);

  /// One fine-level smoother sweep within [lower, upper].
  void smooth(Vector& x, Vector& r, bool forward);

  /// Called after every fine-level sweep of nonlinear_cycle/smooth with the current x, r.
  void set_sweep_hook(std::function<void(const Vector& x, const Vector& r)> hook) {
    sweep_hook_ = std::move(hook);
  }
  const CycleStatistics& statistics() const { return stats_; }

 private:
  struct LevelState;
  void set_truncation(const std::vector<char>& truncated);
  /// P̃_j from level j's truncated set and matrix; sets level j−1's truncated set.
  void truncate_level(int j);
  void rebuild_coarse_levels();
  void recurse(int j, CycleShape shape, Vector& c, Vector& r, const Vector& lo, const Vector& hi,
               bool constrained);
  /// Level j's smoothers for its current matrix.
  void make_smoother(int j);
  void smooth_level(int j, Vector& c, Vector& r, const Vector& lo, const Vector& hi, bool forward);
  void project_obstacle(int j, const Vector& c, const Vector& hi, Vector& coarse_hi) const;
  const SparseMatrix& matrix(int j) const;
  /// The chain's A_j, formed from A_{j+1} first if it was not (GalerkinChain).
  SparseMatrix& chain_matrix(int j);
  /// P̃ᵀAP̃ − PᵀAP on the second-finest level (small: the contact boundary's couplings).
  void truncation_correction(SparseMatrix& out);
  /// Forms the truncated matrix of the second-finest level, in the chain's storage when the
  /// correction stays within its pattern, else in its own.
  void truncate_second_finest();
  const TruncatedProlongation& prolongation(int j) const;

  const BoxQp& qp_;
  const LevelHierarchy& hierarchy_;
  MultilevelOptions options_;
  std::vector<std::unique_ptr<LevelState>> levels_;
  /// revisit_[j]: level j visits level j−1 as the cycle's shape says (else once, with the same
  /// shape); see the constructor.
  std::vector<char> revisit_;
  std::vector<char> truncated_;  ///< the fine truncated set the levels below were built for
  bool built_ = false;
  /// Per level j ≥ 1 (index j): the truncated set of level j (the fine truncated set on the
  /// finest level; S_n DOFs whose fine descendants are all truncated below it) and the
  /// truncated prolongation P̃_j.
  std::vector<std::vector<char>> level_truncated_;
  std::vector<TruncatedProlongation> truncated_prolongations_;
  std::unique_ptr<SparseBoxQpSolver> coarse_solver_;
  std::shared_ptr<GalerkinChain> chain_;
  /// Edits of the chain's second-finest matrix made by the truncation (restored on change).
  std::unique_ptr<ReversibleEdits> top_edits_;
  /// Per level: the weights of the fine S_n of each link in the truncated prolongation.
  std::vector<std::vector<std::array<double, 2>>> sn_weights_;
  std::function<void(const Vector&, const Vector&)> sweep_hook_;
  CycleStatistics stats_;
};

}  // namespace fosls
