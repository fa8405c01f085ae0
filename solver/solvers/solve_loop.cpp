#include "solvers/solve_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/fosls_assert.hpp"
#include "core/indefinite_system.hpp"
#include "core/non_finite.hpp"
#include "core/peak_memory.hpp"
#include "solvers/algebraic_error.hpp"
#include "solvers/algebraic_error_stop.hpp"
#include "solvers/kink_sides.hpp"
#include "solvers/kkt_residual_stop.hpp"
#include "solvers/mmg_step.hpp"
#include "solvers/nested_iteration.hpp"
#include "solvers/pdas_step.hpp"
#include "solvers/pgs_step.hpp"
#include "solvers/rounding_level_stop.hpp"
#include "solvers/subspace_acceleration.hpp"
#include "solvers/tnnmg_step.hpp"

namespace fosls {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

bool is_multilevel(SolverMethod method) {
  return method == SolverMethod::kMmg || method == SolverMethod::kTnnmg;
}

/// The iteration step of the method.
std::unique_ptr<IterationStep> make_step(const BoxQp& qp, const LevelHierarchy& hierarchy,
                                         const SolverOptions& options,
                                         std::shared_ptr<GalerkinChain> chain) {
  switch (options.method) {
    case SolverMethod::kMmg:
      return std::make_unique<MmgStep>(qp, hierarchy, options.multilevel, std::move(chain));
    case SolverMethod::kTnnmg:
      return std::make_unique<TnnmgStep>(qp, hierarchy, options.multilevel, std::move(chain));
    case SolverMethod::kPdas:
      return std::make_unique<PdasStep>(qp);
    case SolverMethod::kPgs:
      return std::make_unique<PgsStep>(qp, hierarchy, options.multilevel);
  }
  return nullptr;
}

/// The stopping criteria in the order they are asked (the first met ends the solve). pdas, not
/// monotone, stops by the KKT test only: its energy history says nothing about its error.
/// With updates of the problem (Coulomb) J jumps at each update, which the algebraic error
/// estimate from J's history does not allow for: the KKT test decides.
std::vector<std::unique_ptr<StoppingCriterion>> stopping_criteria(const BoxQp& qp,
                                                                  const SolverOptions& options,
                                                                  const Vector& x, bool updates,
                                                                  double initial_kkt) {
  std::vector<std::unique_ptr<StoppingCriterion>> criteria;
  const double reference =
      options.reference_kkt > 0.0 && initial_kkt > 0.0 ? options.reference_kkt / initial_kkt : 1.0;
  criteria.push_back(std::make_unique<KktResidualStop>(options.tolerance * reference));
  if (options.stopping == StoppingRule::kDiscretisation && options.method != SolverMethod::kPdas &&
      !updates)
    criteria.push_back(std::make_unique<AlgebraicErrorStop>(options.discretisation_fraction));
  criteria.push_back(std::make_unique<RoundingLevelStop>(qp, x));
  return criteria;
}

/// What became non-finite at iteration k (0: the initial iterate, from the assembled data).
std::string non_finite_message(int k, const IterationRecord& rec) {
  std::ostringstream m;
  m << "the solve produced numbers that are not finite (KKT residual " << rec.kkt_residual
    << ", energy " << rec.energy << (k == 0 ? " at the start" : " at iteration ")
    << (k == 0 ? std::string() : std::to_string(k)) << ")";
  return m.str();
}

/// The iterations of one solve: a step, the residual, the acceleration, the records and the
/// criteria, until one is met, the observer stops it or max_iterations run out.
class IterationLoop {
 public:
  IterationLoop(const BoxQp& qp, IterationStep& step, const SolverOptions& options,
                const SolverObserver& observer, Vector& x, SolverReport& report,
                KinkSides* sides = nullptr, CoulombUpdate* coulomb = nullptr)
      : qp_(qp),
        sides_(sides),
        coulomb_(coulomb),
        step_(step),
        options_(options),
        observer_(observer),
        x_(x),
        report_(report),
        acceleration_(qp),
        accelerate_(is_multilevel(options.method) && options.accelerate) {}

  /// Runs the iterations; report's history, iterations, KKT residuals, convergence and active
  /// set count are set.
  void run() {
    t0_ = Clock::now();
    symmetric_multiply(qp_.A, x_, r_);
    r_ = qp_.b - r_;
    if (sides_) sides_->choose(x_, r_);
    if (coulomb_ && !coulomb_->newton()) update_problem(0);  // the start's own bounds
    active_ = qp_.active_set(x_);
    report_.initial_kkt = record(0, 0.0, 0).kkt_residual;
    if (coulomb_) coulomb_->started(frozen_kkt_);
    report_.final_kkt = report_.initial_kkt;
    report_.converged = report_.initial_kkt == 0.0;
    const auto criteria =
        stopping_criteria(qp_, options_, x_, coulomb_ != nullptr, report_.initial_kkt);
    for (int k = 1; k <= options_.max_iterations && !report_.converged; ++k) {
      if (stopped_by_observer()) break;
      const IterationRecord rec = iterate(k);
      report_.iterations = k;
      report_.final_kkt = rec.kkt_residual;
      for (const auto& criterion : criteria)
        if (criterion->met(report_.history, x_)) {
          report_.converged_by = criterion->reason();
          break;
        }
      const bool met = report_.converged_by != ConvergedBy::kNone;
      // Met on Coulomb's residual, the update (bounds from x's S_n, slipping S_t moved onto
      // them) converges the solve if it changed the bounds by friction_tolerance at most, or
      // moved x by no more than the residual that met the criterion (coulomb_update.hpp).
      if (coulomb_ && (met || coulomb_->due(k, frozen_kkt_, rec.kkt_residual)) &&
          update_problem(k) > options_.friction_tolerance && coulomb_->moved() > rec.kkt_residual)
        report_.converged_by = ConvergedBy::kNone;
      report_.converged = report_.converged_by != ConvergedBy::kNone;
      if (!report_.converged && coulomb_ && coulomb_->stalled(report_.history)) {
        report_.stalled = true;  // the caller's fallback takes over (coulomb_fallback.hpp)
        break;
      }
    }
    if (report_.converged && report_.converged_by == ConvergedBy::kNone)
      report_.converged_by = ConvergedBy::kKktResidual;  // the initial iterate solved it
    report_.active = static_cast<int>(std::count(active_.begin(), active_.end(), 1));
    report_.solve_s = seconds_since(t0_);
  }

 private:
  bool stopped_by_observer() {
    if (observer_.cancelled && observer_.cancelled()) return report_.cancelled = true;
    if (observer_.out_of_time && observer_.out_of_time()) return report_.time_limited = true;
    return false;
  }

  /// Iteration k: the step, the acceleration, the residual recomputed, the checks, the record.
  /// Coulomb's slip bounds from x after iteration k (coulomb_update.hpp): returns their
  /// relative change.
  double update_problem(int k) {
    const double change = coulomb_->apply(k, x_, r_, frozen_kkt_);
    report_.update_changes.push_back(change);
    active_ = qp_.active_set(x_);
    return change;
  }

  IterationRecord iterate(int k) {
    if (sides_) sides_->choose(x_, r_);
    const Vector x_old = x_, r_old = r_;
    step_.iterate(x_, r_);
    if (accelerate_ && acceleration_.accelerate(x_old, r_old, x_, r_) > 0.0)
      ++report_.accelerated_steps;
    // Recompute the residual so that rounding in the incremental updates cannot accumulate.
    symmetric_multiply(qp_.A, x_, r_);
    r_ = qp_.b - r_;
    const Vector dx = x_ - x_old;
    if (accelerate_) acceleration_.remember(x_old, r_old, x_, r_);
    check_invariants(dx, r_old);
    const double correction = std::sqrt(std::max(0.0, dx.dot(r_old - r_)));
    const std::vector<char> now = qp_.active_set(x_);
    int changed = 0;
    for (int i = 0; i < qp_.size(); ++i) changed += now[i] != active_[i];
    active_ = now;
    return record(k, correction, changed);
  }

  void check_invariants([[maybe_unused]] const Vector& dx, [[maybe_unused]] const Vector& r_old) {
    // pdas (semismooth Newton) is not a feasible-path method: its iterates may leave the bounds
    // on the inactive set until the active set is right; every other method keeps them.
    FOSLS_ASSERT(options_.method == SolverMethod::kPdas || qp_.feasible(x_),
                 "every step keeps lower <= x <= upper");
    // J(x) − J(x_old) = −½ dx·(r_old + r); mmg, tnnmg and pgs never increase J, up to rounding:
    // relative to the step's terms, and absolute, of the size of the rounding in r = b − A x
    // (a few ulps of ‖b‖ per entry) times the step — near convergence dx·r is itself that small.
    FOSLS_ASSERT(
        options_.method == SolverMethod::kPdas ||
            -0.5 * dx.dot(r_old + r_) <= 1e-10 * (std::abs(dx.dot(r_old)) + std::abs(dx.dot(r_))) +
                                             1e-12 * dx.norm() * (qp_.b.norm() + r_old.norm()),
        "a monotone method increased J");
  }

  IterationRecord record(int k, double correction, int changed) {
    IterationRecord rec;
    rec.iteration = k;
    rec.energy = qp_.energy_from_residual(x_, r_);
    rec.correction = correction;
    rec.kkt_residual = qp_.kkt_residual(x_, r_);
    if (sides_) {
      rec.energy += sides_->energy_offset();
      const double sided = rec.kkt_residual;
      rec.kkt_residual = sides_->kkt_residual(x_, r_, sided);
      // With Coulomb friction the measure is the residual of Coulomb's law, the bounds' own
      // (the frozen problem's is kept for the update's schedule).
      frozen_kkt_ = rec.kkt_residual;
      if (coulomb_ && !coulomb_->newton()) rec.kkt_residual = coulomb_->residual(x_, r_, sided);
    }
    // A NaN compares false with every tolerance and would pass a stopping test as met.
    if (!std::isfinite(rec.kkt_residual) || !std::isfinite(rec.energy))
      throw NonFiniteError(non_finite_message(k, rec));
    rec.active = static_cast<int>(std::count(active_.begin(), active_.end(), 1));
    rec.changed = changed;
    rec.time_s = seconds_since(t0_);
    report_.history.push_back(rec);
    if (observer_.on_iteration) observer_.on_iteration(rec);
    return rec;
  }

  const BoxQp& qp_;
  KinkSides* sides_;
  CoulombUpdate* coulomb_;
  double frozen_kkt_ = 0.0;  ///< the kinked residual with the current (frozen) bounds
  IterationStep& step_;
  const SolverOptions& options_;
  const SolverObserver& observer_;
  Vector& x_;
  SolverReport& report_;
  SubspaceAcceleration acceleration_;
  const bool accelerate_;
  Vector r_;
  std::vector<char> active_;
  Clock::time_point t0_;
};

/// x within the bounds (zero when it has the wrong size).
void start_feasible(const BoxQp& qp, Vector& x) {
  if (x.size() != qp.size()) x = Vector::Zero(qp.size());
  qp.clip(x);
}

/// The error estimates, the asymptotic rate, the cycle's statistics and the message of a
/// finished solve.
void summarise(const SolverOptions& options, const IterationStep& step, SolverReport& report) {
  // pdas does not decrease J monotonically: its energy history says nothing about its error.
  report.algebraic_error = options.method == SolverMethod::kPdas
                               ? std::numeric_limits<double>::infinity()
                               : std::sqrt(energy_error_estimate(report.history));
  report.estimator = std::sqrt(std::max(0.0, report.history.back().energy));
  const int h = static_cast<int>(report.history.size());
  if (h >= 2) {
    const int span = std::min(5, h - 1);
    const double a = report.history[h - 1 - span].kkt_residual,
                 b = report.history[h - 1].kkt_residual;
    report.asymptotic_rate = a > 0 && b > 0 ? std::pow(b / a, 1.0 / span) : 0.0;
  }
  report.cycle = step.statistics();
  if (report.cancelled)
    report.message = "cancelled after " + std::to_string(report.iterations) + " iterations";
  else if (!report.converged)
    report.message = "not converged: the KKT residual fell by a factor " +
                     std::to_string(report.final_kkt / report.initial_kkt) + " in " +
                     std::to_string(report.iterations) + " iterations, tolerance " +
                     std::to_string(options.tolerance);
}

}  // namespace

namespace {

/// solve_with_chain's work, with the kinks' sides and the problem's update when there are.
SolverReport solve_from_start(const BoxQp& qp, const LevelHierarchy& hierarchy,
                              const SolverOptions& options, const SolverObserver& observer,
                              Vector& x, std::shared_ptr<GalerkinChain> chain, KinkSides* sides,
                              CoulombUpdate* coulomb) {
  SolverReport report;
  const auto t_setup = Clock::now();
  start_feasible(qp, x);
  if (is_multilevel(options.method)) {
    if (!chain) chain = std::make_shared<GalerkinChain>(galerkin_chain(qp.A, hierarchy));
    if (options.nested) {
      // Where the nested iteration cannot start (one level, or x = 0 infeasible) x stays as is.
      const auto t_nested = Clock::now();
      nested_initial_guess(qp, hierarchy, options, *chain, x, report, observer.out_of_time);
      report.nested_s = seconds_since(t_nested);
    }
  }
  const std::unique_ptr<IterationStep> step = make_step(qp, hierarchy, options, chain);
  if (observer.on_sweep)
    step->set_sweep_hook([&](const Vector& xs, const Vector& rs) {
      observer.on_sweep(qp.energy_from_residual(xs, rs) + (sides ? sides->energy_offset() : 0.0));
    });
  report.setup_s = seconds_since(t_setup);
  report.setup_mib = peak_rss_mib();
  IterationLoop(qp, *step, options, observer, x, report, sides, coulomb).run();
  summarise(options, *step, report);
  return report;
}

/// The Galerkin chain (mmg, tnnmg; checked for definiteness when asked), then the solve.
SolverReport solve_with_new_chain(const BoxQp& qp, const LevelHierarchy& hierarchy,
                                  const SolverOptions& options, const SolverObserver& observer,
                                  Vector& x, KinkSides* sides, CoulombUpdate* coulomb) {
  const bool multilevel = is_multilevel(options.method);
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
  const double chain_s = seconds_since(t0);
  const double chain_mib = multilevel ? peak_rss_mib() : 0.0;
  SolverReport report =
      solve_from_start(qp, hierarchy, options, observer, x, chain, sides, coulomb);
  report.setup_s += chain_s;
  report.chain_mib = chain_mib;
  return report;
}

}  // namespace

SolverReport solve_box_qp(const BoxQp& qp, const LevelHierarchy& hierarchy,
                          const SolverOptions& options, const SolverObserver& observer, Vector& x) {
  return solve_with_new_chain(qp, hierarchy, options, observer, x, nullptr, nullptr);
}

SolverReport solve_with_chain(const BoxQp& qp, const LevelHierarchy& hierarchy,
                              const SolverOptions& options, const SolverObserver& observer,
                              Vector& x, std::shared_ptr<GalerkinChain> chain) {
  return solve_from_start(qp, hierarchy, options, observer, x, std::move(chain), nullptr, nullptr);
}

namespace {

/// One frictional solve by options.method with the schedule given (or pdas's own).
SolverReport solve_sided(BoxQp& qp, const KinkedProblem& kinked, const CoulombSchedule& schedule,
                         const LevelHierarchy& hierarchy, const SolverOptions& options,
                         const SolverObserver& observer, Vector& x) {
  const bool pdas = options.method == SolverMethod::kPdas;
  KinkSides sides(qp, *kinked.kinks, pdas);
  std::optional<CoulombUpdate> coulomb;
  if (kinked.coulomb)
    coulomb.emplace(qp, *kinked.coulomb, *kinked.kinks, sides,
                    pdas ? CoulombSchedule::newton_schedule() : schedule);
  return solve_with_new_chain(qp, hierarchy, options, observer, x, &sides,
                              coulomb ? &*coulomb : nullptr);
}

}  // namespace

SolverReport solve_kinked_qp(BoxQp& qp, const KinkedProblem& kinked,
                             const LevelHierarchy& hierarchy, const SolverOptions& options,
                             const SolverObserver& observer, Vector& x) {
  // tnnmg's linear correction and line search see the sided QP's kinks as bounds it would
  // cross in one Newton step; it is not extended to them.
  if (options.method == SolverMethod::kTnnmg)
    throw std::invalid_argument("solver.method tnnmg does not handle friction");
  // Coulomb with mmg: where it stalls, pdas finishes from its iterate, with the bounds of its
  // last update (they stay in qp) and the tolerance relative to mmg's initial residual.
  const bool fallback = kinked.coulomb && options.method == SolverMethod::kMmg &&
                        options.coulomb_fallback && qp.size() <= kFallbackMaxUnknowns;
  CoulombSchedule schedule = kinked.schedule;
  if (!fallback)
    schedule.stall = StallTest::never();
  else if (schedule.stall.window == 0)
    schedule.stall = StallTest{};  // the measured default unless the caller gives one
  SolverReport report = solve_sided(qp, kinked, schedule, hierarchy, options, observer, x);
  if (!report.stalled) return report;
  SolverOptions newton = options;
  newton.method = SolverMethod::kPdas;
  newton.max_iterations = options.max_iterations - report.iterations;
  newton.reference_kkt = report.initial_kkt;
  // The observer sees one solve: pdas's iterations numbered on from mmg's, its start not again.
  SolverObserver continued = observer;
  if (observer.on_iteration)
    continued.on_iteration = [&observer, &report](IterationRecord rec) {
      if (rec.iteration == 0) return;
      rec.iteration += report.iterations;
      rec.time_s += report.solve_s;
      observer.on_iteration(rec);
    };
  append_fallback(report, solve_sided(qp, kinked, schedule, hierarchy, newton, continued, x));
  return report;
}

}  // namespace fosls
