#pragma once
// Acceleration of a monotone iteration by exact minimisation over the last two steps
// (docs/method.md §4.5): conjugate-direction (CG-like) acceleration that keeps every iterate
// feasible and never increases J.

#include "core/box_qp.hpp"

namespace fosls {

class SubspaceAcceleration {
 public:
  explicit SubspaceAcceleration(const BoxQp& qp) : qp_(qp) {}

  /// x_old, r_old: the iterate and residual before the method's step; x, r: after it (both
  /// feasible). Replaces x by the minimiser of J over x_old + span{x − x_old, previous step},
  /// moved back towards the method's iterate as far as the bounds require; r follows
  /// incrementally. Returns the fraction t ∈ [0, 1] of the extra move that was taken.
  double accelerate(const Vector& x_old, const Vector& r_old, Vector& x, Vector& r);

  /// Records the step actually taken (x − x_old) and its image A(x − x_old) = r_old − r with
  /// the recomputed residual, as the previous direction of the next call.
  void remember(const Vector& x_old, const Vector& r_old, const Vector& x, const Vector& r);

 private:
  const BoxQp& qp_;
  Vector p_, ap_;  ///< previous step and A times it (empty before the first step)
};

}  // namespace fosls
