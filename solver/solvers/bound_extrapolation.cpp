#include "solvers/bound_extrapolation.hpp"

#include <Eigen/QR>
#include <algorithm>

namespace fosls {

namespace {

/// The plain update's contraction from which on the bounds are extrapolated.
constexpr double kSlow = 0.4;
/// How many plain updates' length an extrapolation may move the bounds beyond g.
constexpr double kLimit = 3.0;

/// Whether a and b are positive at the same entries: the same edges in contact.
bool same_support(const Vector& a, const Vector& b) {
  for (Eigen::Index e = 0; e < a.size(); ++e)
    if ((a[e] > 0.0) != (b[e] > 0.0)) return false;
  return true;
}

}  // namespace

Vector BoundExtrapolation::next(const Vector& s, const Vector& g) {
  // Across a change of the contact set the map is another one: its history says nothing.
  if (!history_.empty() && !same_support(history_.back().g, g)) history_.clear();
  history_.push_back({g, g - s});
  while (static_cast<int>(history_.size()) > depth_ + 1) history_.pop_front();
  const int m = static_cast<int>(history_.size()) - 1;
  if (m == 0) return g;
  // A fixed point that contracts fast needs no help, and there the differences are mostly the
  // inexact iteration's noise: extrapolating them cost the press step of cattaneo_mindlin at
  // refinements 5 four iterations (docs/method.md §8.4).
  if (history_[m].f.norm() < kSlow * history_[m - 1].f.norm()) return g;
  // min_γ ‖f_k − ΔF γ‖ over the differences of successive residuals; s_{k+1} = g_k − ΔG γ.
  Eigen::MatrixXd dF(g.size(), m), dG(g.size(), m);
  for (int j = 0; j < m; ++j) {
    dF.col(j) = history_[j + 1].f - history_[j].f;
    dG.col(j) = history_[j + 1].g - history_[j].g;
  }
  const Eigen::VectorXd gamma = dF.colPivHouseholderQr().solve(history_.back().f);
  Vector next = g - dG * gamma;
  // A combination that moves the bounds further from g than kLimit plain updates would is an
  // extrapolation the history does not support (nearly dependent differences): g instead.
  if (!((next - g).norm() <= kLimit * history_.back().f.norm())) {
    history_.clear();
    history_.push_back({g, g - s});
    return g;
  }
  for (Eigen::Index e = 0; e < next.size(); ++e)
    next[e] = g[e] > 0.0 ? std::max(0.0, next[e]) : 0.0;
  return next;
}

}  // namespace fosls
