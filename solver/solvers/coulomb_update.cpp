#include "solvers/coulomb_update.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solvers/smoother.hpp"

namespace fosls {

CoulombUpdate::CoulombUpdate(BoxQp& qp, const FrictionLayout& layout, Kinks& kinks,
                             KinkSides& sides, CoulombSchedule schedule)
    : qp_(qp),
      layout_(layout),
      kinks_(kinks),
      sides_(sides),
      schedule_(schedule),
      extrapolation_(schedule.extrapolation_depth),
      bounds_(layout.edges.size()) {}

double CoulombUpdate::set_bounds(const Vector& x) {
  return set_friction_bounds(layout_, x, qp_, kinks_,
                             [this](const Vector& s, const Vector& g, bool first) -> Vector {
                               if (!first) return extrapolation_.next(s, g);
                               extrapolation_.reset();
                               return g;
                             });
}

double CoulombUpdate::residual(const Vector& x, const Vector& r, double sided_kkt) const {
  // Only the S_t of the frictional edges and the kinked U_t see the bounds: their terms of the
  // sided residual are exchanged for those with the trial bounds.
  double sum = sided_kkt * sided_kkt;
  for (std::size_t e = 0; e < layout_.edges.size(); ++e) {
    const FrictionEdge& f = layout_.edges[e];
    const int i = f.st;
    const double s = slip_bound(f, x);
    bounds_[e] = s;
    const double frozen = x[i] - std::clamp(x[i] + r[i], qp_.lower[i], qp_.upper[i]);
    const double trial = x[i] - std::clamp(x[i] + r[i], -s, s);
    sum += trial * trial - frozen * frozen;
  }
  Kinks trial = kinks_;
  set_kink_weights(layout_, bounds_, trial);
  weights_.swap(trial.weight);
  return sides_.kkt_residual(x, r, std::sqrt(std::max(0.0, sum)), weights_);
}

bool CoulombUpdate::due(int k, double frozen, double coulomb) const {
  return k - last_update_ >= schedule_.max_iterations || frozen <= schedule_.ratio * coulomb ||
         frozen <= schedule_.reduction * frozen_at_update_;
}

double CoulombUpdate::apply(int k, Vector& x, Vector& r, double frozen) {
  last_update_ = k;
  frozen_at_update_ = frozen;
  if (schedule_.newton) {
    // pdas's iterates may lie outside any bound until its active set is right: all clipped.
    // Its measure is the frozen problem's residual, which does not bound Coulomb's: the bounds'
    // change alone decides its convergence.
    moved_ = std::numeric_limits<double>::infinity();
    const double change = set_bounds(x);
    qp_.clip(x);
    symmetric_multiply(qp_.A, x, r);
    r = qp_.b - r;
    sides_.choose(x, r);
    return change;
  }
  std::vector<signed char> slipping(layout_.edges.size(), 0);
  for (std::size_t e = 0; e < layout_.edges.size(); ++e) {
    const int i = layout_.edges[e].st;
    // A bound of 0 (an open edge) holds S_t at 0: that is no slip.
    if (qp_.upper[i] > 0.0 && x[i] >= qp_.upper[i]) slipping[e] = 1;
    if (qp_.upper[i] > 0.0 && x[i] <= qp_.lower[i]) slipping[e] = -1;
  }
  // The map from the bounds to 𝔣|S_n| is smooth only while the edges keep their states: the
  // extrapolation combines updates between which no edge started or stopped slipping (with
  // edges changing state it cost the L-bracket 6 iterations, docs/validation.md §13).
  if (slipping != slipping_) extrapolation_.reset();
  slipping_ = slipping;
  const double change = set_bounds(x);
  double moved_squared = 0.0;
  for (std::size_t e = 0; e < layout_.edges.size(); ++e) {
    const int i = layout_.edges[e].st;
    const double moved = slipping[e] > 0   ? qp_.upper[i]
                         : slipping[e] < 0 ? qp_.lower[i]
                                           : std::clamp(x[i], qp_.lower[i], qp_.upper[i]);
    if (moved == x[i]) continue;
    moved_squared += (moved - x[i]) * (moved - x[i]);
    update_residual(qp_.A, i, moved - x[i], r);
    x[i] = moved;
  }
  moved_ = std::sqrt(moved_squared);
  sides_.choose(x, r);
  return change;
}

}  // namespace fosls
