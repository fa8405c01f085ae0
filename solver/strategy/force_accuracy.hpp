#pragma once
// The error of the contact force estimated from the forces of successive uniform refinements
// (docs/method.md §9): the change of the force from the last level, divided by ρ − 1, where ρ
// is the ratio by which the change shrinks per refinement — the ratio of the last two changes
// once three levels are solved, limited to [2, 4], and 2 before. A geometric sequence of
// changes with ratio ρ leaves exactly that much to the limit. A force whose last two changes
// have opposite signs is not on such a sequence: its estimate is the larger change. A force whose
// change grew (monotonically) is not yet on one either: it has no estimate until it shrinks.
// On adaptive levels the same reasoning runs against the unknowns instead of the level count
// (estimate_adaptive_force_error).

#include <limits>
#include <string>
#include <vector>

namespace fosls {

/// A force's components: 2 in 2D, 3 in 3D.
using ForceComponents = std::vector<double>;

/// The ratio assumed before one is observed: the slowest the limits allow (order one in h, as
/// near re-entrant corners), so that two levels never claim more than the last change.
constexpr double kAssumedForceRatio = 2.0;
/// The limits of an observed ratio: 4 is the lowest-order method's h² (a larger observed
/// ratio is a lucky step, not a faster method); 2 is order one in h.
constexpr double kMinForceRatio = 2.0;
constexpr double kMaxForceRatio = 4.0;
/// With an accuracy section each level's solve stops at this fraction of its discretisation
/// error unless the case gives one: the force's change between levels must be the
/// discretisation's, and 0.1 (the default) leaves enough algebraic error in the force to spoil
/// it (docs/validation.md §14).
constexpr double kAccuracyDiscretisationFraction = 0.01;
/// The growth of the unknowns across which an adaptive sequence's change is taken: a step of
/// Dörfler marking adds 1.3–1.8 times the unknowns, and its change is as much the marking's
/// wander as convergence (docs/validation.md §14).
constexpr double kAdaptiveSpan = 2.0;

struct ForceErrorEstimate {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  double change = kNone;  ///< |F_k − F_(k−1)| / |F_k|
  double ratio = kNone;   ///< ρ used
  bool ratio_observed = false;
  /// The last two changes point the same way along F_k. When they do not, the force is not
  /// converging monotonically (errors of two signs cancel in a change), and the estimate is the
  /// larger of the two changes instead.
  bool monotone = true;
  /// The last change is larger than the one before, on a monotone sequence: the levels are not
  /// yet where the change shrinks geometrically, and change / (ρ − 1) with the clamped ρ would
  /// understate the error (hertz_3d's uniform refinement 3: 2.3 % claimed, 4.6 % true;
  /// docs/validation.md §16). No estimate then: the loop refines on before it claims.
  bool growing = false;
  double estimate = kNone;  ///< the estimated relative error of |F_k|; NaN: none yet
  /// An adaptive estimate from a single span, whose direction no earlier span could check: it
  /// is reported, and the loop refines on instead of claiming from it (docs/method.md §9).
  bool single_span = false;
  bool available() const { return estimate == estimate; }
};

/// The estimate after the last of `forces`, one per level, coarsest first, each level a uniform
/// refinement of the one before. None with one level or a zero last force.
ForceErrorEstimate estimate_force_error(const std::vector<ForceComponents>& forces);

/// The estimate after the last of `forces` on adaptively refined levels with `dofs` unknowns
/// (docs/method.md §9): the model |F_k − F| = C N_k^(−p), applied across a span — from the
/// last level with at most 1/kAdaptiveSpan of the last level's unknowns — instead of one step,
/// with p from the span before (limited to [1/dim, 2/dim], the h-orders 1 and 2 of the uniform
/// rule) or 1/dim before one is observed. `ratio` is the equivalent ρ of a uniform refinement,
/// 2^(dim·p). None until a span exists.
ForceErrorEstimate estimate_adaptive_force_error(const std::vector<ForceComponents>& forces,
                                                 const std::vector<long long>& dofs, int dim);

/// Why the run stops after the last of `forces` (`reached` with an estimate within `tolerance`
/// that is not a single span's; `no_force` when it and the level before are zero), or empty to
/// refine on.
std::string accuracy_stop_reason(const ForceErrorEstimate& e, double tolerance,
                                 const std::vector<ForceComponents>& forces);

/// |F|: std::hypot of the 2 or 3 components (2D's hypot(x, y) exactly).
double force_norm(const ForceComponents& f);

}  // namespace fosls
