#pragma once
// The kinks of a frictional problem (core/kinks.hpp) for the box-QP methods (docs/method.md §8):
// before each iteration every kinked DOF is held on one side of its kink — above it (the kink
// is the linear term +w, the kink its lower bound), below it, or at it (both bounds there) —
// chosen from the iterate and the subgradient (a kink of weight 0 is no kink and gets no side).
// On its side J + kinks is a box QP up to a constant, so each monotone step on it decreases the
// kinked functional and keeps feasibility; a DOF that reaches its kink is given a new side in
// the next iteration. The QP's b and bounds are changed at the kinked DOFs only and restored
// when the sides go.

#include <vector>

#include "core/box_qp.hpp"
#include "core/kinks.hpp"

namespace fosls {

class KinkSides {
 public:
  /// `newton`: for pdas, whose iterates may cross a kink in one step, the side is that of the
  /// prox point x − ∇/A_ii (a semismooth Newton step on the kink) instead of x's own.
  KinkSides(BoxQp& qp, const Kinks& kinks, bool newton = false);
  ~KinkSides();
  KinkSides(const KinkSides&) = delete;
  KinkSides& operator=(const KinkSides&) = delete;

  /// Sides for x (r = b − A x of the sided QP in and out: b changes at the kinked DOFs).
  void choose(const Vector& x, Vector& r);
  /// The kinked functional minus the sided QP's J at a point on the chosen sides.
  double energy_offset() const;
  /// ‖x − prox(x − ∇)‖ of the kinked problem from the sided KKT residual and r.
  double kkt_residual(const Vector& x, const Vector& r, double sided_kkt) const;
  /// The same with the kinks weighted by `weights` instead of their own (Coulomb's residual:
  /// the weights of the bounds the iterate gives, solvers/coulomb_update.hpp).
  double kkt_residual(const Vector& x, const Vector& r, double sided_kkt,
                      const std::vector<double>& weights) const;
  /// Whether kink k's DOF sits at its kink (stick).
  bool at_kink(const Vector& x, int k) const { return x[kinks_.dof[k]] == kinks_.at[k]; }

 private:
  BoxQp& qp_;
  const Kinks& kinks_;
  Vector b_, lower_, upper_;  ///< the QP's own values at the kinked DOFs
  Vector diagonal_;           ///< A_ii at the kinked DOFs (newton only)
  std::vector<signed char> side_;
};

}  // namespace fosls
