#include "solvers/solve_loop.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/fosls_assert.hpp"
#include "core/indefinite_system.hpp"
#include "core/peak_memory.hpp"
#include "solvers/algebraic_error.hpp"
#include "solvers/subspace_acceleration.hpp"

namespace fosls {

bool chain_is_definite(const SparseMatrix& A, const GalerkinChain& chain, int max_dofs) {
  const SparseMatrix* checked = chain.matrices.empty() ? &A : &chain.matrices[0];
  for (const SparseMatrix& m : chain.matrices)
    if (m.rows() <= max_dofs) checked = &m;
  if (A.rows() <= max_dofs) checked = &A;
  Eigen::CholmodSupernodalLLT<SparseMatrix> llt(*checked);
  return llt.info() == Eigen::Success;
}

const char* converged_by_name(ConvergedBy c) {
  switch (c) {
    case ConvergedBy::kKktResidual:
      return "kkt_residual";
    case ConvergedBy::kAlgebraicError:
      return "algebraic_error";
    case ConvergedBy::kRoundingLevel:
      return "rounding_level";
    case ConvergedBy::kNone:
      break;
  }
  return "none";
}

const char* method_name(SolverMethod m) {
  switch (m) {
    case SolverMethod::kMmg:
      return "mmg";
    case SolverMethod::kTnnmg:
      return "tnnmg";
    case SolverMethod::kPdas:
      return "pdas";
    case SolverMethod::kPgs:
      return "pgs";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;

/// Active set of an iterate: bounded DOFs at their bound.
std::vector<char> active_set(const BoxQp& qp, const Vector& x) {
  std::vector<char> a(x.size(), 0);
  for (int i = 0; i < x.size(); ++i) a[i] = is_at_bound(x[i], qp.lower[i], qp.upper[i]);
  return a;
}

/// One iteration of a method: x and r = b − A x in, the next iterate out.
class Step {
 public:
  virtual ~Step() = default;
  virtual void iterate(Vector& x, Vector& r) = 0;
  virtual CycleStatistics statistics() const { return {}; }
};

class MmgStep : public Step {
 public:
  MmgStep(const BoxQp& qp, const LevelHierarchy& h, const MultilevelOptions& o,
          std::shared_ptr<GalerkinChain> chain)
      : cycle_(qp, h, o, std::move(chain)) {}
  void iterate(Vector& x, Vector& r) override { cycle_.nonlinear_cycle(x, r); }
  CycleStatistics statistics() const override { return cycle_.statistics(); }
  MultilevelCycle& cycle() { return cycle_; }

 private:
  MultilevelCycle cycle_;
};

class PgsStep : public Step {
 public:
  PgsStep(const BoxQp& qp, const LevelHierarchy& h, const MultilevelOptions& o) : qp_(qp) {
    if (o.smoother == SmootherType::kPatch)
      patch_ = std::make_unique<PatchSmoother>(qp.A, h.levels.back().patches,
                                               h.levels.back().patch_split);
    else
      point_ = std::make_unique<PointSmoother>(qp.A);
  }
  void iterate(Vector& x, Vector& r) override {
    if (patch_)
      patch_->sweep(x, r, qp_.lower, qp_.upper, true);
    else
      point_->sweep(x, r, qp_.lower, qp_.upper, true);
  }
  CycleStatistics statistics() const override {
    CycleStatistics s;
    s.double_precision_smoothers = patch_ && !patch_->single_precision() ? 1 : 0;
    return s;
  }

 private:
  const BoxQp& qp_;
  std::unique_ptr<PatchSmoother> patch_;
  std::unique_ptr<PointSmoother> point_;
};

/// Gräser & Kornhuber: non-linear smoothing, one truncated linear cycle (V or W, as the
/// multilevel method's) on the inactive set, projection onto the bounds, exact line search on J.
class TnnmgStep : public Step {
 public:
  TnnmgStep(const BoxQp& qp, const LevelHierarchy& h, const MultilevelOptions& o,
            std::shared_ptr<GalerkinChain> chain)
      : qp_(qp), options_(o), cycle_(qp, h, o, std::move(chain)) {}
  void iterate(Vector& x, Vector& r) override {
    for (int s = 0; s < std::max(1, options_.pre_smoothing); ++s) cycle_.smooth(x, r, true);
    const std::vector<char> frozen = active_set(qp_, x);
    Vector c = Vector::Zero(x.size()), rc = r;
    cycle_.linear_cycle(frozen, c, rc);
    Vector d(x.size());
    for (int i = 0; i < x.size(); ++i)
      d[i] = std::clamp(x[i] + c[i], qp_.lower[i], qp_.upper[i]) - x[i];
    Vector ad;
    symmetric_multiply(qp_.A, d, ad);
    const double curvature = d.dot(ad);
    const double alpha = curvature > 0 ? std::clamp(r.dot(d) / curvature, 0.0, 1.0) : 0.0;
    if (alpha > 0) {
      for (int i = 0; i < x.size(); ++i)
        x[i] = alpha == 1.0 ? x[i] + d[i]
                            : std::clamp(x[i] + alpha * d[i], qp_.lower[i], qp_.upper[i]);
      // Land exactly on bounds reached by the projection.
      if (alpha == 1.0)
        for (int i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], qp_.lower[i], qp_.upper[i]);
      r -= alpha * ad;
    }
    for (int s = 0; s < options_.post_smoothing; ++s) cycle_.smooth(x, r, false);
  }
  CycleStatistics statistics() const override { return cycle_.statistics(); }

 private:
  const BoxQp& qp_;
  MultilevelOptions options_;
  MultilevelCycle cycle_;
};

/// Semismooth Newton / primal–dual active set with a CHOLMOD factorisation: the pattern is
/// analysed once, the numeric factorisation is redone for every active set (rows and columns
/// of active DOFs replaced by the identity, so the pattern never changes).
class PdasStep : public Step {
 public:
  explicit PdasStep(const BoxQp& qp) : qp_(qp), m_(qp.A), diagonal_(qp.A.diagonal()) {
    llt_.analyzePattern(m_);
    if (llt_.info() != Eigen::Success)
      throw std::runtime_error("CHOLMOD could not analyse the matrix");
  }
  void iterate(Vector& x, Vector& r) override {
    const int n = qp_.size();
    // Active-set test λ_i + c_i (x_i − ψ_i) > 0 with λ = b − A x on the current active set
    // (zero elsewhere) and c_i = A_ii, which makes the test invariant to scaling of DOFs.
    // The first iteration takes λ = b − A x everywhere as its multiplier estimate.
    std::vector<char> active(n, 0);
    for (int i = 0; i < n; ++i) {
      if (!is_bounded_above(qp_.upper[i])) continue;
      const double lambda = (first_ || current_[i]) ? r[i] : 0.0;
      active[i] = lambda + diagonal_[i] * (x[i] - qp_.upper[i]) > 0;
    }
    first_ = false;
    current_ = active;
    // M = A with active rows/columns replaced by the identity; same pattern as A.
    Vector rhs = qp_.b;
    Vector psi = Vector::Zero(n);
    for (int i = 0; i < n; ++i)
      if (active[i]) psi[i] = qp_.upper[i];
    Vector apsi;
    symmetric_multiply(qp_.A, psi, apsi);
    for (int i = 0; i < n; ++i) rhs[i] = active[i] ? psi[i] : rhs[i] - apsi[i];
    const int* outer = qp_.A.outerIndexPtr();
    const int* inner = qp_.A.innerIndexPtr();
    const double* a = qp_.A.valuePtr();
    double* m = m_.valuePtr();
    for (int col = 0; col < n; ++col)
      for (int k = outer[col]; k < outer[col + 1]; ++k) {
        const int row = inner[k];
        m[k] = (active[row] || active[col]) ? (row == col ? 1.0 : 0.0) : a[k];
      }
    llt_.factorize(m_);
    if (llt_.info() != Eigen::Success)
      throw IndefiniteSystemError("CHOLMOD: the matrix is not positive definite");
    x = llt_.solve(rhs);
    for (int i = 0; i < n; ++i)
      if (active[i]) x[i] = qp_.upper[i];
    Vector ax;
    symmetric_multiply(qp_.A, x, ax);
    r = qp_.b - ax;
  }

 private:
  const BoxQp& qp_;
  SparseMatrix m_;
  Vector diagonal_;
  Eigen::CholmodSupernodalLLT<SparseMatrix> llt_;
  std::vector<char> current_;
  bool first_ = true;
};

/// The Galerkin problem of level j−1 seen from the problem of level j at x = 0: A_{j−1} = PᵀAP
/// (from the chain), b_{j−1} = Pᵀb and upper bounds by the coarse-obstacle projection of the
/// level-j bounds.
BoxQp coarser_problem(const BoxQp& fine, const Level& level, CoarseProjection projection) {
  const SparseMatrix& p = level.prolongation;
  BoxQp c;  // c.A is the chain's matrix, lent to the problem while it is solved
  c.b = p.transpose() * fine.b;
  const int n = static_cast<int>(p.cols());
  c.lower = Vector::Constant(n, -kNoBound);
  c.upper = Vector::Constant(n, kNoBound);
  Vector defect(fine.size());
  for (int i = 0; i < fine.size(); ++i)
    defect[i] = is_bounded_above(fine.upper[i]) ? fine.upper[i] : kNoBound;
  project_defect(level, projection, defect, c.upper);
  return c;
}

/// Nested iteration: the initial iterate of the finest level from solves on the coarser ones.
/// Returns false (x untouched) when x = 0 is not feasible, e.g. for a negative gap.
SolverReport solve_with_chain(const BoxQp& qp, const LevelHierarchy& hierarchy,
                              const SolverOptions& options, const SolverObserver& observer,
                              Vector& x, std::shared_ptr<GalerkinChain> chain);

/// Lends matrices to the nested solves by swapping them in, and takes them back however the
/// solve ends: each coarse problem and sub-chain would otherwise hold a copy of the chain's
/// matrices (at level 7 of the square the largest allocation of the nested iteration).
class LentMatrices {
 public:
  void lend(SparseMatrix& owner, SparseMatrix& borrower) {
    owner.swap(borrower);
    loans_.emplace_back(&owner, &borrower);
  }
  ~LentMatrices() {
    for (auto& [owner, borrower] : loans_) owner->swap(*borrower);
  }

 private:
  std::vector<std::pair<SparseMatrix*, SparseMatrix*>> loans_;
};

bool nested_initial_guess(const BoxQp& qp, const LevelHierarchy& h, const SolverOptions& options,
                          GalerkinChain& chain, Vector& x, SolverReport& report) {
  const int top = h.num_levels() - 1;
  if (top < 1) return false;
  for (int i = 0; i < qp.size(); ++i)
    if (qp.lower[i] > 0 || qp.upper[i] < 0) return false;
  std::vector<BoxQp> problems(top);
  for (int j = top; j >= 1; --j)
    problems[j - 1] =
        coarser_problem(j == top ? qp : problems[j], h.levels[j], options.multilevel.projection);
  SolverOptions inner = options;
  inner.nested = false;
  inner.stopping = StoppingRule::kKktResidual;
  inner.tolerance = options.nested_tolerance;
  inner.max_iterations = options.nested_max_iterations;
  Vector xc;
  for (int j = 0; j < top; ++j) {
    LevelHierarchy sub;
    sub.levels.assign(h.levels.begin(), h.levels.begin() + j + 1);
    auto sub_chain = std::make_shared<GalerkinChain>();
    sub_chain->matrices.resize(j);
    LentMatrices lent;
    lent.lend(chain.matrices[j], problems[j].A);
    for (int k = 0; k < j; ++k) lent.lend(chain.matrices[k], sub_chain->matrices[k]);
    if (j > 0) {
      xc = h.levels[j].prolongation * xc;
      for (int i = 0; i < xc.size(); ++i)
        xc[i] = std::clamp(xc[i], problems[j].lower[i], problems[j].upper[i]);
    }
    // The coarsest level is solved by pdas on CHOLMOD: a handful of factorisations. (The cycle's
    // exact coarse solver, then a primal active-set method, refactorised once per bound it met:
    // from x = 0 on a coarsest level of 15 000 unknowns with ~100 contact bounds — the rounded
    // punch, whose coarse levels are dropped by the normal-turn rule — it took 6.5 s of a
    // 9.6 s solve.) The initial guess needs no monotone path: it is clipped to the bounds.
    if (j == 0) inner.method = SolverMethod::kPdas;
    const SolverReport r = solve_with_chain(problems[j], sub, inner, {}, xc, sub_chain);
    inner.method = options.method;
    report.nested_iterations.push_back(r.iterations);
  }
  x = h.levels[top].prolongation * xc;
  for (int i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], qp.lower[i], qp.upper[i]);
  return true;
}

}  // namespace

SolverReport solve_box_qp(const BoxQp& qp, const LevelHierarchy& hierarchy,
                          const SolverOptions& options, const SolverObserver& observer, Vector& x) {
  const bool multilevel =
      options.method == SolverMethod::kMmg || options.method == SolverMethod::kTnnmg;
  const auto t0 = Clock::now();
  std::shared_ptr<GalerkinChain> chain;
  if (multilevel) {
    // The definiteness check and the nested iteration read the coarse levels' untruncated
    // matrices; without them a solve needs only the second-finest one up front (the rest is
    // formed if a cycle runs untruncated): an adaptive step from its prolongated start.
    const bool whole_chain = options.check_definiteness || options.nested;
    chain = std::make_shared<GalerkinChain>(
        galerkin_chain(qp.A, hierarchy, whole_chain ? std::numeric_limits<int>::max() : 1));
    if (options.check_definiteness && !chain_is_definite(qp.A, *chain))
      throw IndefiniteSystemError("the FOSLS matrix is not positive definite");
  }
  const double chain_s = std::chrono::duration<double>(Clock::now() - t0).count();
  const double chain_mib = multilevel ? peak_rss_mib() : 0.0;
  SolverReport report = solve_with_chain(qp, hierarchy, options, observer, x, chain);
  report.setup_s += chain_s;
  report.chain_mib = chain_mib;
  return report;
}

namespace {

SolverReport solve_with_chain(const BoxQp& qp, const LevelHierarchy& hierarchy,
                              const SolverOptions& options, const SolverObserver& observer,
                              Vector& x, std::shared_ptr<GalerkinChain> chain) {
  SolverReport report;
  const auto t_setup = Clock::now();
  const int n = qp.size();
  if (x.size() != n) x = Vector::Zero(n);
  for (int i = 0; i < n; ++i) x[i] = std::clamp(x[i], qp.lower[i], qp.upper[i]);

  const bool multilevel =
      options.method == SolverMethod::kMmg || options.method == SolverMethod::kTnnmg;
  if (multilevel && !chain)
    chain = std::make_shared<GalerkinChain>(galerkin_chain(qp.A, hierarchy));
  if (multilevel && options.nested) {
    const auto t_nested = Clock::now();
    nested_initial_guess(qp, hierarchy, options, *chain, x, report);
    report.nested_s = std::chrono::duration<double>(Clock::now() - t_nested).count();
  }
  std::unique_ptr<Step> step;
  MultilevelCycle* cycle = nullptr;
  switch (options.method) {
    case SolverMethod::kMmg: {
      auto s = std::make_unique<MmgStep>(qp, hierarchy, options.multilevel, chain);
      cycle = &s->cycle();
      step = std::move(s);
      break;
    }
    case SolverMethod::kTnnmg:
      step = std::make_unique<TnnmgStep>(qp, hierarchy, options.multilevel, chain);
      break;
    case SolverMethod::kPdas:
      step = std::make_unique<PdasStep>(qp);
      break;
    case SolverMethod::kPgs:
      step = std::make_unique<PgsStep>(qp, hierarchy, options.multilevel);
      break;
  }
  if (cycle && observer.on_sweep)
    cycle->set_sweep_hook([&](const Vector& xs, const Vector& rs) {
      observer.on_sweep(qp.energy_from_residual(xs, rs));
    });
  report.setup_s = std::chrono::duration<double>(Clock::now() - t_setup).count();
  report.setup_mib = peak_rss_mib();

  const auto t0 = Clock::now();
  Vector r;
  symmetric_multiply(qp.A, x, r);
  r = qp.b - r;
  std::vector<char> active = active_set(qp, x);
  auto record = [&](int k, double correction, int changed) {
    IterationRecord rec;
    rec.iteration = k;
    rec.energy = qp.energy_from_residual(x, r);
    rec.correction = correction;
    rec.kkt_residual = qp.kkt_residual(x, r);
    rec.active = static_cast<int>(std::count(active.begin(), active.end(), 1));
    rec.changed = changed;
    rec.time_s = std::chrono::duration<double>(Clock::now() - t0).count();
    report.history.push_back(rec);
    if (observer.on_iteration) observer.on_iteration(rec);
    return rec;
  };
  SubspaceAcceleration acceleration(qp);
  const bool accelerate = multilevel && options.accelerate;
  report.initial_kkt = record(0, 0.0, 0).kkt_residual;
  report.final_kkt = report.initial_kkt;
  report.converged = report.initial_kkt == 0.0;
  const bool by_discretisation =
      options.stopping == StoppingRule::kDiscretisation && options.method != SolverMethod::kPdas;
  // A tolerance relative to a small initial residual (a prolongated or continued start) can lie
  // below the rounding level: the residual then stalls between 0.5 and 7 times that level and
  // the solve ran to max_iterations (31 instead of 16 iterations on an adaptive Hertz step at
  // 10⁻⁸; a step at 10⁻¹⁰ stopped the adaptive run as not converged). Near the level, a solve
  // stops once the residual has also stalled: it did not halve against the better of the two
  // iterations before, so a residual still falling fast reaches its tolerance as before. The
  // level is recomputed at x only near it, or once the residual has fallen by 10⁻⁶ (the level
  // from the start can be far too small when x started at 0).
  double rounding_level = qp.rounding_level(x);
  auto at_rounding_level = [&](double kkt) {
    const int h = static_cast<int>(report.history.size());  // the last record is kkt's
    if (h < 3) return false;
    const double before =
        std::min(report.history[h - 2].kkt_residual, report.history[h - 3].kkt_residual);
    if (kkt < 0.5 * before) return false;
    if (kkt > 1e3 * kRoundingLevelFactor * rounding_level && kkt > 1e-6 * report.initial_kkt)
      return false;
    rounding_level = qp.rounding_level(x);
    return kkt <= kRoundingLevelFactor * rounding_level;
  };
  for (int k = 1; k <= options.max_iterations && !report.converged; ++k) {
    if (observer.cancelled && observer.cancelled()) {
      report.cancelled = true;
      break;
    }
    if (observer.out_of_time && observer.out_of_time()) {
      report.time_limited = true;
      break;
    }
    const Vector x_old = x, r_old = r;
    step->iterate(x, r);
    if (accelerate && acceleration.accelerate(x_old, r_old, x, r) > 0.0) ++report.accelerated_steps;
    // Recompute the residual so that rounding in the incremental updates cannot accumulate.
    symmetric_multiply(qp.A, x, r);
    r = qp.b - r;
    const Vector dx = x - x_old;
    if (accelerate) acceleration.remember(x_old, r_old, x, r);
    // pdas (semismooth Newton) is not a feasible-path method: its iterates may leave the bounds
    // on the inactive set until the active set is right; every other method keeps them.
    FOSLS_ASSERT(options.method == SolverMethod::kPdas || qp.feasible(x),
                 "every step keeps lower <= x <= upper");
    // J(x) − J(x_old) = −½ dx·(r_old + r); mmg, tnnmg and pgs never increase J, up to rounding:
    // relative to the step's terms, and absolute, of the size of the rounding in r = b − A x
    // (a few ulps of ‖b‖ per entry) times the step — near convergence dx·r is itself that small.
    FOSLS_ASSERT(
        options.method == SolverMethod::kPdas ||
            -0.5 * dx.dot(r_old + r) <= 1e-10 * (std::abs(dx.dot(r_old)) + std::abs(dx.dot(r))) +
                                            1e-12 * dx.norm() * (qp.b.norm() + r_old.norm()),
        "a monotone method increased J");
    const double correction = std::sqrt(std::max(0.0, dx.dot(r_old - r)));
    const std::vector<char> now = active_set(qp, x);
    int changed = 0;
    for (int i = 0; i < n; ++i) changed += now[i] != active[i];
    active = now;
    const IterationRecord rec = record(k, correction, changed);
    report.iterations = k;
    report.final_kkt = rec.kkt_residual;
    if (rec.kkt_residual <= options.tolerance * report.initial_kkt)
      report.converged_by = ConvergedBy::kKktResidual;
    else if (by_discretisation &&
             algebraic_error_is_small(report.history, options.discretisation_fraction))
      report.converged_by = ConvergedBy::kAlgebraicError;
    else if (at_rounding_level(rec.kkt_residual))
      report.converged_by = ConvergedBy::kRoundingLevel;
    report.converged = report.converged_by != ConvergedBy::kNone;
  }
  if (report.converged && report.converged_by == ConvergedBy::kNone)
    report.converged_by = ConvergedBy::kKktResidual;  // the initial iterate solved it
  // pdas does not decrease J monotonically: its energy history says nothing about its error.
  report.algebraic_error = options.method == SolverMethod::kPdas
                               ? std::numeric_limits<double>::infinity()
                               : std::sqrt(energy_error_estimate(report.history));
  report.estimator = std::sqrt(std::max(0.0, report.history.back().energy));
  report.active = static_cast<int>(std::count(active.begin(), active.end(), 1));
  const int h = static_cast<int>(report.history.size());
  if (h >= 2) {
    const int span = std::min(5, h - 1);
    const double a = report.history[h - 1 - span].kkt_residual,
                 b = report.history[h - 1].kkt_residual;
    report.asymptotic_rate = a > 0 && b > 0 ? std::pow(b / a, 1.0 / span) : 0.0;
  }
  report.solve_s = std::chrono::duration<double>(Clock::now() - t0).count();
  report.cycle = step->statistics();
  if (report.cancelled)
    report.message = "cancelled after " + std::to_string(report.iterations) + " iterations";
  else if (!report.converged)
    report.message = "not converged: the KKT residual fell by a factor " +
                     std::to_string(report.final_kkt / report.initial_kkt) + " in " +
                     std::to_string(report.iterations) + " iterations, tolerance " +
                     std::to_string(options.tolerance);
  return report;
}

}  // namespace

}  // namespace fosls
