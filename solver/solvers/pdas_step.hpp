#pragma once
// Semismooth Newton / primal–dual active set with a CHOLMOD factorisation: the direct
// comparison method. The pattern is analysed once, the numeric factorisation is redone for
// every active set (rows and columns of active DOFs replaced by the identity, so the pattern
// never changes). Not a feasible-path method: iterates may leave the bounds on the inactive
// set until the active set is right.

#include <Eigen/CholmodSupport>
#include <vector>

#include "solvers/iteration_step.hpp"

namespace fosls {

class PdasStep : public IterationStep {
 public:
  explicit PdasStep(const BoxQp& qp);
  void iterate(Vector& x, Vector& r) override;

 private:
  static constexpr char kUpper = 1, kLower = 2;
  /// The bound a DOF is active at.
  double bound(char side, int i) const { return side == kUpper ? qp_.upper[i] : qp_.lower[i]; }
  /// The active set of the next Newton step: the DOFs whose multiplier test says so.
  std::vector<char> next_active_set(const Vector& x, const Vector& r);
  /// A with the rows and columns of active DOFs replaced by the identity, into m_'s values.
  void hold_active_rows(const std::vector<char>& active);

  const BoxQp& qp_;
  SparseMatrix m_;
  Vector diagonal_;
  Eigen::CholmodSupernodalLLT<SparseMatrix> llt_;
  std::vector<char> current_;
  bool first_ = true;
};

}  // namespace fosls
