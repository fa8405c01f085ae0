#pragma once
// Semismooth Newton / primal–dual active set with a CHOLMOD factorisation: the direct
// comparison method. Each iteration solves A x = b on the inactive DOFs with the active ones
// held at their bounds. Two ways to that solve:
//  - where one factorisation of A costs more than kComplementMinFlops (3D's levels), one
//    factorisation per problem with the bounded DOFs ordered last and the inverse of their
//    Schur complement (solvers/bounded_complement_solver.hpp): per active set two solves and a
//    dense factorisation of the active DOFs' block;
//  - otherwise (and where that does not apply), the pattern is analysed once and the numeric
//    factorisation is redone for every active set (rows and columns of active DOFs replaced by
//    the identity, so the pattern never changes).
// Not a feasible-path method: iterates may leave the bounds on the inactive set until the
// active set is right.

#include <Eigen/CholmodSupport>
#include <memory>
#include <vector>

#include "solvers/bounded_complement_solver.hpp"
#include "solvers/iteration_step.hpp"

namespace fosls {

class PdasStep : public IterationStep {
 public:
  /// The factorisation work (CHOLMOD's flop count) from which the bounded DOFs' complement is
  /// used: 3D's quarter ball from its first level (1.3·10⁹ at 19 784 unknowns), none of the
  /// shipped 2D examples (docs/performance.md, "Where the accuracy run's time goes").
  static constexpr double kComplementMinFlops = 1e9;

  /// complement_min_flops: where the complement starts to be used (tests set 0 or infinity).
  explicit PdasStep(const BoxQp& qp, double complement_min_flops = kComplementMinFlops);
  void iterate(Vector& x, Vector& r) override;

 private:
  static constexpr char kUpper = 1, kLower = 2;
  /// The bound a DOF is active at.
  double bound(char side, int i) const { return side == kUpper ? qp_.upper[i] : qp_.lower[i]; }
  /// The active set of the next Newton step: the DOFs whose multiplier test says so.
  std::vector<char> next_active_set(const Vector& x, const Vector& r);
  /// A with the rows and columns of active DOFs replaced by the identity, into m_'s values.
  void hold_active_rows(const std::vector<char>& active);
  /// x for the active set by a numeric factorisation of the held-rows matrix.
  void solve_by_factorisation(const std::vector<char>& active, const Vector& psi, Vector& x);

  const BoxQp& qp_;
  SparseMatrix m_;
  Vector diagonal_;
  Eigen::CholmodSupernodalLLT<SparseMatrix> llt_;
  bool analysed_ = false;  // m_ and llt_'s pattern: on the first factorisation
  std::unique_ptr<BoundedComplementSolver> complement_;
  std::vector<char> current_;
  bool first_ = true;
};

}  // namespace fosls
