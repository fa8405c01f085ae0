#include "solvers/multilevel_cycle.hpp"

#include <algorithm>
#include <chrono>

#include "core/fosls_assert.hpp"
#include "core/indefinite_system.hpp"
#include "solvers/row_obstacle.hpp"

namespace fosls {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

constexpr double kRevisitFactor = 2;

/// The chain of the cycle: `chain`, or formed here; after checking that the hierarchy fits qp.
std::shared_ptr<GalerkinChain> checked_chain(const BoxQp& qp, const LevelHierarchy& hierarchy,
                                             std::shared_ptr<GalerkinChain> chain) {
  FOSLS_ASSERT(hierarchy_inconsistency(hierarchy, qp.size()).empty(),
               hierarchy_inconsistency(hierarchy, qp.size()));
  if (chain) return chain;
  return std::make_shared<GalerkinChain>(galerkin_chain(qp.A, hierarchy));
}

}  // namespace

MultilevelCycle::MultilevelCycle(const BoxQp& qp, const LevelHierarchy& hierarchy,
                                 MultilevelOptions options, std::shared_ptr<GalerkinChain> chain)
    : qp_(qp),
      hierarchy_(hierarchy),
      options_(options),
      truncation_(qp, hierarchy, checked_chain(qp, hierarchy, std::move(chain))),
      smoothers_(hierarchy.num_levels()) {
  const int nl = hierarchy.num_levels();
  // A W-cycle's second visit of the coarser levels is affordable only where the unknowns have
  // fallen by a large enough factor since the last level that made one. A factor 2 keeps every
  // uniform level (factor ≈ 4) revisiting, as before, and on bisection levels (factor ≈ 1.1
  // to 1.5 each) revisits where the size has halved: a level of N_k unknowns is then visited
  // at most N/N_k times, so a cycle costs O(N log N) instead of the W-cycle's (γ/1.5)^levels
  // N, with the iterations of the W-cycle, where a V-cycle's grow with the adaptive steps
  // (docs/performance.md, "Measurements behind choices in the code").
  revisit_.assign(nl, 0);
  if (!qp.row_obstacles.empty()) {
    row_bounded_.resize(nl);
    row_bounded_[nl - 1].assign(qp.size(), 0);
    for (int i : qp.row_obstacles) row_bounded_[nl - 1][i] = 1;
  }
  long long reference = qp.size();
  for (int j = nl - 1; j >= 2; --j) {
    const long long coarse = hierarchy.levels[j - 1].num_dofs;
    if (kRevisitFactor * coarse < reference) revisit_[j] = 1, reference = coarse;
  }
  // The finest matrix never changes: its smoothers are built once, here. The coarse levels are
  // built by the first set_truncation, for the first cycle's truncated set: building them
  // untruncated here as well was one full rebuild per solve that a constrained problem threw
  // away at once (docs/performance.md, adaptivity). A single level has no coarse levels to wait
  // for, only its exact solver.
  make_smoothers(nl - 1);
  if (nl == 1) set_truncation(std::vector<char>(qp.size(), 0));
}

MultilevelCycle::~MultilevelCycle() = default;

void MultilevelCycle::set_truncation(const std::vector<char>& truncated) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!truncation_.set_truncation(truncated, [this](int j) { make_smoothers(j); })) return;
  // A new truncation changes the coarse matrix's values, rarely its pattern: a held-rows solver
  // keeps its ordering and analysis, which on a large 3D coarse mesh cost as much as the
  // factorisation (docs/performance.md, "A large coarse mesh was expensive in 3D").
  const SparseMatrix& coarse = truncation_.matrix(0);
  bool refactored = false;
  try {
    refactored = coarse_solver_ && coarse_solver_->refactor(coarse);
  } catch (...) {
    coarse_solver_.reset();  // half refactored: no solver is left to be used
    throw;
  }
  if (!refactored) {
    coarse_solver_.reset();  // released before its successor is built
    coarse_solver_ =
        std::make_unique<SparseBoxQpSolver>(coarse, hierarchy_.levels[0].block_factorization);
  }
  ++stats_.galerkin_rebuilds;
  stats_.galerkin_s += seconds_since(t0);
}

void MultilevelCycle::make_smoothers(int j) {
  LevelSmoothers& s = smoothers_[j];
  const SparseMatrix& a = truncation_.matrix(j);
  const Level& level = hierarchy_.levels[j];
  s.smoother.reset();  // released before its successor is built
  s.smoother = smoother_info(options_.smoother).make(a, level);
  if (s.smoother->double_precision_factors()) ++stats_.double_precision_smoothers;
  s.strip.reset();
  if (options_.strip && !level.contact_strip.empty())
    s.strip = std::make_unique<StripSmoother>(a, level.contact_strip, level.block_factorization);
}

void MultilevelCycle::smooth_level(int j, Vector& c, Vector& r, const Vector& lo, const Vector& hi,
                                   bool forward) {
  const auto t0 = std::chrono::steady_clock::now();
  const LevelSmoothers& s = smoothers_[j];
  s.smoother->sweep(c, r, lo, hi, forward);
  stats_.smoothing_s += seconds_since(t0);
  if (s.strip) {
    const auto t1 = std::chrono::steady_clock::now();
    s.strip->sweep(c, r, lo, hi, forward);
    stats_.strip_s += seconds_since(t1);
  }
}

void MultilevelCycle::after_fine_sweep(int j, const Vector& c, const Vector& r) const {
  if (j == hierarchy_.num_levels() - 1 && sweep_hook_) sweep_hook_(c, r);
}

void MultilevelCycle::smooth(Vector& x, Vector& r, bool forward) {
  const int top = hierarchy_.num_levels() - 1;
  smooth_level(top, x, r, qp_.lower, qp_.upper, forward);
  if (sweep_hook_) sweep_hook_(x, r);
}

void MultilevelCycle::project_obstacle(int j, const Vector& c, const Vector& hi,
                                       Vector& coarse_hi) const {
  Vector defect(c.size());
  for (int i = 0; i < c.size(); ++i)
    defect[i] = (!is_bounded_above(hi[i]) || truncation_.truncated(j)[i])
                    ? kNoBound
                    : std::max(0.0, hi[i] - c[i]);
  project_defect(hierarchy_.levels[j], options_.projection, defect, coarse_hi,
                 &truncation_.sn_weights(j));
}

void MultilevelCycle::solve_coarsest(Vector& c, Vector& r, const Vector& lo, const Vector& hi) {
  const auto t0 = std::chrono::steady_clock::now();
  const int n = static_cast<int>(c.size());
  Vector dlo(n), dhi(n), delta;
  for (int i = 0; i < n; ++i) {
    dlo[i] = std::min(0.0, lo[i] - c[i]);
    dhi[i] = std::max(0.0, hi[i] - c[i]);
  }
  // A free block that is not definite (the matrix is, so only rounding gets here) must not
  // pass as a zero correction: the cycle would stop moving and look converged.
  if (!coarse_solver_->solve(r, dlo, dhi, delta))
    throw IndefiniteSystemError(
        "the coarsest level's matrix is not positive definite on a free set");
  step_within_bounds(c, 1.0, delta, lo, hi);  // delta becomes the change of c
  r -= truncation_.matrix(0) * delta;
  stats_.coarse_s += seconds_since(t0);
}

void MultilevelCycle::coarse_correction(int j, CycleShape shape, Vector& c, Vector& r,
                                        const Vector& lo, const Vector& hi, bool constrained) {
  const TruncatedProlongation& P = truncation_.prolongation(j);
  const int nc = P.cols();
  Vector rc;
  P.restrict_to(r, rc);
  Vector lo_c = Vector::Constant(nc, -kNoBound), hi_c = Vector::Constant(nc, kNoBound);
  if (constrained) project_obstacle(j, c, hi, hi_c);
  if (constrained && !row_bounded_.empty())
    project_row_obstacles(P, row_bounded_[j], truncation_.truncated(j), c, lo, hi, lo_c, hi_c,
                          row_bounded_[j - 1]);
  Vector cc = Vector::Zero(nc);
  // W and F visit the coarse problem twice; its bounds are on the total coarse correction, so
  // the second visit continues from the first (each visit is monotone, hence both are).
  recurse(j - 1, shape, cc, rc, lo_c, hi_c, constrained);
  if (revisit_[j] && shape != CycleShape::kV)
    recurse(j - 1, shape == CycleShape::kF ? CycleShape::kV : shape, cc, rc, lo_c, hi_c,
            constrained);
  Vector v;
  P.prolongate(cc, v);
  // Safeguard: the projections make K_{j−1} ⊂ K_j exactly where contact normals agree
  // between levels; on curved boundaries the shortened step keeps every iterate feasible,
  // and J still decreases since J is convex and the coarse correction lowers it.
  const double alpha = constrained ? max_feasible_step(c, v, lo, hi) : 1.0;
  if (alpha < 1.0) ++stats_.safeguard_reductions;
  if (alpha > 0.0) {
    step_within_bounds(c, alpha, v, lo, hi);  // v becomes the change of c: one vector fewer
    Vector ac;
    symmetric_multiply(truncation_.matrix(j), v, ac);
    r -= ac;
  }
}

void MultilevelCycle::recurse(int j, CycleShape shape, Vector& c, Vector& r, const Vector& lo,
                              const Vector& hi, bool constrained) {
  const int top = hierarchy_.num_levels() - 1;
  if (j == 0) {
    solve_coarsest(c, r, lo, hi);
    after_fine_sweep(j, c, r);
    return;
  }
  for (int s = 0; s < options_.pre_smoothing; ++s) {
    smooth_level(j, c, r, lo, hi, true);
    after_fine_sweep(j, c, r);
  }
  if (j == top && constrained) {
    // N•: bounded fine DOFs at their bound after smoothing.
    std::vector<char> active(c.size(), 0);
    for (int i = 0; i < c.size(); ++i) active[i] = is_at_bound(c[i], lo[i], hi[i]);
    set_truncation(active);
  }
  coarse_correction(j, shape, c, r, lo, hi, constrained);
  after_fine_sweep(j, c, r);
  for (int s = 0; s < options_.post_smoothing; ++s) {
    smooth_level(j, c, r, lo, hi, false);
    after_fine_sweep(j, c, r);
  }
}

void MultilevelCycle::nonlinear_cycle(Vector& x, Vector& r) {
  recurse(hierarchy_.num_levels() - 1, options_.cycle, x, r, qp_.lower, qp_.upper, true);
}

void MultilevelCycle::linear_cycle(const std::vector<char>& frozen, Vector& c, Vector& r) {
  const int n = qp_.size();
  set_truncation(frozen);
  Vector lo = Vector::Constant(n, -kNoBound), hi = Vector::Constant(n, kNoBound);
  for (int i = 0; i < n; ++i)
    if (frozen[i]) lo[i] = hi[i] = 0.0;
  auto hook = std::move(sweep_hook_);
  sweep_hook_ = nullptr;
  recurse(hierarchy_.num_levels() - 1, options_.cycle, c, r, lo, hi, false);
  sweep_hook_ = std::move(hook);
}

}  // namespace fosls
