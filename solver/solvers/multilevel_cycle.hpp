#pragma once
// The monotone multilevel cycle of docs/method.md §4 (a W-cycle by default; V and F on
// request): smoothing (smoother_table.hpp, strip_smoother.hpp), truncated coarse basis
// (truncated_hierarchy.hpp), coarse obstacles by non-linear projection (coarse_obstacle.hpp),
// exact coarsest solve, prolongation. This file is the recursion.
//
// Convention: a cycle works on an iterate and its residual in place. On the finest level the
// iterate is x itself (bounds = the problem's bounds); on coarser levels it is the correction
// c_j, starting at 0, with the bounds carried down from the level above.

#include <functional>
#include <memory>
#include <vector>

#include "core/box_qp.hpp"
#include "core/level_hierarchy.hpp"
#include "solvers/coarse_obstacle.hpp"
#include "solvers/exact_box_qp.hpp"
#include "solvers/galerkin_chain.hpp"
#include "solvers/smoother_table.hpp"
#include "solvers/strip_smoother.hpp"
#include "solvers/truncated_hierarchy.hpp"

namespace fosls {

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
  /// The smoothers of a level: the chosen one and, along the contact boundary, the strip.
  struct LevelSmoothers {
    std::unique_ptr<Smoother> smoother;
    std::unique_ptr<StripSmoother> strip;
  };

  /// The truncation of the levels below for the fine truncated set; their smoothers and the
  /// coarsest level's exact solver follow it.
  void set_truncation(const std::vector<char>& truncated);
  void recurse(int j, CycleShape shape, Vector& c, Vector& r, const Vector& lo, const Vector& hi,
               bool constrained);
  /// The exact solve of the coarsest level within [lo, hi].
  void solve_coarsest(Vector& c, Vector& r, const Vector& lo, const Vector& hi);
  /// Level j's coarse correction: restriction, the visits of level j−1 and the prolongated
  /// correction, shortened where it would leave [lo, hi].
  void coarse_correction(int j, CycleShape shape, Vector& c, Vector& r, const Vector& lo,
                         const Vector& hi, bool constrained);
  /// Level j's smoothers for its current matrix.
  void make_smoothers(int j);
  void smooth_level(int j, Vector& c, Vector& r, const Vector& lo, const Vector& hi, bool forward);
  void project_obstacle(int j, const Vector& c, const Vector& hi, Vector& coarse_hi) const;
  /// Calls the sweep hook when j is the finest level.
  void after_fine_sweep(int j, const Vector& c, const Vector& r) const;

  const BoxQp& qp_;
  const LevelHierarchy& hierarchy_;
  MultilevelOptions options_;
  TruncatedHierarchy truncation_;
  std::vector<LevelSmoothers> smoothers_;
  /// revisit_[j]: level j visits level j−1 as the cycle's shape says (else once, with the same
  /// shape); see the constructor.
  std::vector<char> revisit_;
  /// Per level, the DOFs whose bounds go to the next coarser level by the rows of P̃
  /// (row_obstacle.hpp): on the finest the QP's row_obstacles; empty without them.
  std::vector<std::vector<char>> row_bounded_;
  std::unique_ptr<SparseBoxQpSolver> coarse_solver_;
  std::function<void(const Vector&, const Vector&)> sweep_hook_;
  CycleStatistics stats_;
};

}  // namespace fosls
