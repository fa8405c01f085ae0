#pragma once
// Anderson acceleration of Coulomb's fixed point on the slip bounds (docs/method.md §8.4). The
// update maps the bounds s the iteration ran with to G(s) = 𝔣 max(0, −S_n) of the iterate; where
// the active set has settled that map is close to affine and its fixed point is approached
// linearly, at the rate of its largest eigenvalue (0.4–0.65 per update on the robustness cases
// with 𝔣 = 0.3). Anderson's method (Walker & Ni, SIAM J. Numer. Anal. 49, 2011) takes the
// combination of the last few G(s_j) whose residuals G(s_j) − s_j combine to the smallest one:
// a secant method on the fixed point, which needs neither the map's derivative nor a symmetric
// problem. It extrapolates only where the plain updates contract slowly (by less than 0.4 from
// one to the next) and neither the contact set nor an edge's slip has changed, and never far beyond
// G(s): elsewhere the bounds are G(s), as without it.

#include <deque>

#include "core/box_qp.hpp"

namespace fosls {

class BoundExtrapolation {
 public:
  /// `depth`: how many earlier updates the combination may use (0: G(s) itself).
  explicit BoundExtrapolation(int depth) : depth_(depth) {}

  /// The next bounds from the bounds `s` the iteration ran with and the map's value `g` there;
  /// non-negative, and 0 wherever g is 0 (an edge out of contact has no friction).
  Vector next(const Vector& s, const Vector& g);

  /// Forgets the history (bounds set other than by `next`).
  void reset() { history_.clear(); }

 private:
  struct Pair {
    Vector g, f;  ///< G(s) and G(s) − s
  };
  int depth_;
  std::deque<Pair> history_;
};

}  // namespace fosls
