#pragma once
// CHOLMOD through Eigen, with its failures seen. CHOLMOD reports a failed allocation in its
// status instead of throwing, and Eigen 3.4's wrapper does not look: after an analysis that ran
// out of memory the next factorisation dereferences the missing symbolic factor, and after a
// factorisation that did, `info()` can say Success for a factor that was never computed — a
// coarse solve that then returned nothing let a job end "succeeded" with a zero force.
// These calls turn CHOLMOD's out-of-memory (and too-large) status into std::bad_alloc, which the
// programs report as the run's named failure ("ran out of memory"), and any other error status
// into std::runtime_error; a matrix that is not positive definite stays `info() != Success`.

#include <Eigen/CholmodSupport>

#include "core/box_qp.hpp"

namespace fosls {

/// Throws for an error status of CHOLMOD's last call (`what` names the call for the message).
void check_cholmod_status(const cholmod_common& common, const char* what);

/// analyzePattern, checked: a symbolic factor exists afterwards or this has thrown.
template <class Llt>
void analyse_checked(Llt& llt, const SparseMatrix& a) {
  llt.analyzePattern(a);
  check_cholmod_status(llt.cholmod(), "the symbolic analysis");
}

/// factorize, checked; true when the matrix was positive definite.
template <class Llt>
bool factorize_checked(Llt& llt, const SparseMatrix& a) {
  llt.factorize(a);
  check_cholmod_status(llt.cholmod(), "the factorisation");
  return llt.info() == Eigen::Success;
}

/// compute (analysis and factorisation), checked; true when the matrix was positive definite.
template <class Llt>
bool compute_checked(Llt& llt, const SparseMatrix& a) {
  analyse_checked(llt, a);
  return factorize_checked(llt, a);
}

/// x = A⁻¹ b with the factor, checked (a solve allocates its result).
template <class Llt>
Vector solve_checked(Llt& llt, const Vector& b) {
  Vector x = llt.solve(b);
  check_cholmod_status(llt.cholmod(), "the triangular solves");
  return x;
}

}  // namespace fosls
