#pragma once
// Coulomb friction inside the iteration (docs/method.md §8.4). The slip bound of a frictional
// edge, s̄_e = 𝔣 max(0, −S_n,e), depends on the solution; each iteration of the method works on
// the Tresca problem with the bounds frozen, and between iterations the bounds are updated from
// the iterate (`apply`): the S_t of a slipping edge moves with its bound, so the edge keeps
// slipping, and the iterate stays feasible for the bounds it is measured with. How far the
// iterate is from Coulomb's law is the complementarity residual with the bounds the iterate
// itself gives (`residual`), the loop's stopping measure.

#include <vector>

#include "core/box_qp.hpp"
#include "core/friction_law.hpp"
#include "core/kinks.hpp"
#include "solvers/bound_extrapolation.hpp"
#include "solvers/coulomb_fallback.hpp"
#include "solvers/kink_sides.hpp"

namespace fosls {

/// When the bounds are updated: after at most `max_iterations` iterations on the same bounds,
/// and earlier once the residual of the frozen (Tresca) problem is below `ratio` times the
/// Coulomb residual — the iterate then solves the frozen problem better than the frozen problem
/// is Coulomb's, and further iterations on it would be wasted.
/// `newton()` is pdas's schedule, the one before issue 49: no update at the start, an update
/// once the frozen problem's residual has fallen by `reduction` since the last one, S_t clipped
/// to the new bounds (not moved with them), and the frozen problem's residual as the measure.
/// pdas is a Newton method whose iterates leave the bounds until its active set is right; with
/// the schedule above it did not converge on tests/robustness/cases/wedge_tip.json with
/// 𝔣 = 0.3 (200 iterations) where this one takes 24 (94 before the bounds were extrapolated).
struct CoulombSchedule {
  int max_iterations = 3;
  double ratio = 0.0;
  double reduction = 0.0;
  bool newton = false;
  /// How many earlier updates Anderson's extrapolation of the bounds may combine
  /// (solvers/bound_extrapolation.hpp; 0: the bounds are 𝔣 max(0, −S_n) of the iterate).
  int extrapolation_depth = 2;
  /// When the iteration has stalled and a fallback should take over (never by default).
  StallTest stall = StallTest::never();
  static CoulombSchedule newton_schedule() { return {1 << 30, 0.0, 0.3, true, 2}; }
};

class CoulombUpdate {
 public:
  /// `layout` describes the frictional edges of `qp`, whose S_t bounds and kink weights (in
  /// `kinks`, chosen into sides by `sides`) this sets.
  CoulombUpdate(BoxQp& qp, const FrictionLayout& layout, Kinks& kinks, KinkSides& sides,
                CoulombSchedule schedule = {});

  /// ‖x − prox(x − ∇J)‖ with the bounds and kink weights of x's own S_n, from the sided KKT
  /// residual of the current bounds `sided_kkt` and r = b − A x of the sided QP: zero exactly at
  /// a solution of the discrete Coulomb problem. Changes nothing.
  double residual(const Vector& x, const Vector& r, double sided_kkt) const;

  /// The frozen problem's residual at the start (after the start's update): the reference of
  /// the schedule's `reduction` until the next update.
  void started(double frozen) { frozen_at_update_ = frozen; }
  /// pdas's schedule (CoulombSchedule::newton_schedule).
  bool newton() const { return schedule_.newton; }
  /// Whether the iteration of `history` has stalled (the schedule's StallTest).
  bool stalled(const std::vector<IterationRecord>& history) const {
    return schedule_.stall.stalled(history);
  }

  /// Whether iteration k, after which the frozen problem's residual is `frozen` and Coulomb's
  /// `coulomb`, is followed by an update.
  bool due(int k, double frozen, double coulomb) const;

  /// The bounds and kink weights from x's S_n after iteration k (`frozen`: the frozen problem's
  /// residual there); the S_t of every edge that slipped on its old
  /// bound is put on its new one, every S_t is clipped to its new bounds, r kept equal to b − A x
  /// and the kinks' sides chosen again. Returns the largest change of a bound relative to the
  /// largest bound (1 the first time).
  double apply(int k, Vector& x, Vector& r, double frozen);

  /// ‖Δx‖ of the last update: how far it moved S_t onto the new bounds. Where x met a stopping
  /// criterion on Coulomb's residual and the update moved it by no more than that residual, the
  /// updated x is as close to Coulomb's law as the criterion asks, whatever the bounds' change.
  double moved() const { return moved_; }

 private:
  /// Sets the bounds and kink weights from x's S_n, extrapolated over the earlier updates
  /// (none the first time); returns the largest |𝔣 max(0, −S_n) − s̄| relative to the largest
  /// 𝔣 max(0, −S_n), s̄ the bounds x was iterated with (1 the first time).
  double set_bounds(const Vector& x);

  BoxQp& qp_;
  const FrictionLayout& layout_;
  Kinks& kinks_;
  KinkSides& sides_;
  CoulombSchedule schedule_;
  int last_update_ = 0;
  double frozen_at_update_ = 0.0;
  double moved_ = 0.0;
  BoundExtrapolation extrapolation_;
  std::vector<signed char> slipping_;             ///< each edge's slip direction at the last update
  mutable std::vector<double> bounds_, weights_;  ///< of the residual's trial bounds
};

}  // namespace fosls
