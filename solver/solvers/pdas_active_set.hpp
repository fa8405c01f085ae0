#pragma once
// pdas's active-set test (semismooth Newton on the box constraints, docs/method.md §7): which
// DOFs the next Newton step holds at a bound. Shared by the exact step (pdas_step.hpp, CHOLMOD)
// and the inexact one (inexact_pdas_step.hpp, multilevel cycles).

#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

class PdasActiveSet {
 public:
  static constexpr char kUpper = 1, kLower = 2;

  explicit PdasActiveSet(const BoxQp& qp) : qp_(qp), diagonal_(qp.A.diagonal()) {}

  /// The active set of the next Newton step from x and r = b − A x: kUpper or kLower per DOF,
  /// 0 for inactive. Remembers it: the next test takes its multipliers on it.
  std::vector<char> next(const Vector& x, const Vector& r);
  /// The bound a DOF is active at.
  double bound(char side, int i) const { return side == kUpper ? qp_.upper[i] : qp_.lower[i]; }
  /// ψ: the bounds of the active DOFs, 0 elsewhere.
  Vector held_values(const std::vector<char>& active) const;

 private:
  const BoxQp& qp_;
  Vector diagonal_;
  std::vector<char> current_;
  bool first_ = true;
};

}  // namespace fosls
