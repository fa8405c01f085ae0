#include "solvers/bounded_complement_solver.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "solvers/cholmod_checks.hpp"

namespace fosls {

namespace {

/// A CHOLMOD view of A's lower triangle (no copy; CHOLMOD reads it only), as Eigen's wrapper
/// passes a symmetric matrix.
cholmod_sparse view_lower(const SparseMatrix& a) {
  cholmod_sparse s{};
  s.nrow = s.ncol = static_cast<size_t>(a.rows());
  s.nzmax = static_cast<size_t>(a.nonZeros());
  s.p = const_cast<int*>(a.outerIndexPtr());
  s.i = const_cast<int*>(a.innerIndexPtr());
  s.x = const_cast<double*>(a.valuePtr());
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

}  // namespace

std::unique_ptr<BoundedComplementSolver> BoundedComplementSolver::make(
    const SparseMatrix& a, const std::vector<int>& bounded, double min_flops) {
  std::unique_ptr<BoundedComplementSolver> solver(new BoundedComplementSolver);
  cholmod_start(&solver->common_);
  solver->started_ = true;
  // Eigen's CholmodSupernodalLLT's settings.
  solver->common_.final_asis = 1;
  solver->common_.supernodal = CHOLMOD_SUPERNODAL;
  if (bounded.empty() || !solver->analyse(a, bounded, min_flops)) return nullptr;
  cholmod_sparse view = view_lower(a);
  cholmod_factorize(&view, solver->factor_, &solver->common_);
  check_cholmod_status(solver->common_, "the factorisation");
  // Not positive definite without held rows (a body held by its contact alone): the caller's
  // per-active-set factorisation decides.
  if (solver->common_.status != CHOLMOD_OK) return nullptr;
  solver->invert_complement();
  return solver;
}

BoundedComplementSolver::~BoundedComplementSolver() {
  if (!started_) return;
  cholmod_free_factor(&factor_, &common_);
  cholmod_finish(&common_);
}

bool BoundedComplementSolver::analyse(const SparseMatrix& a, const std::vector<int>& bounded,
                                      double min_flops) {
  cholmod_sparse view = view_lower(a);
  cholmod_factor* plain = cholmod_analyze(&view, &common_);
  check_cholmod_status(common_, "the symbolic analysis");
  // Forming G (|B|³ flops) and each G_HH's factorisation (≤ |B|³/3) a tenth of a sparse
  // factorisation at most, and G no larger than the factor.
  const double m = static_cast<double>(bounded.size());
  if (common_.fl < min_flops || m * m * m > 0.1 * common_.fl || m * m > common_.lnz) {
    cholmod_free_factor(&plain, &common_);
    return false;
  }
  const int n = static_cast<int>(a.rows());
  std::vector<char> is_bounded(n, 0);
  for (const int i : bounded) is_bounded[i] = 1;
  // The fill-reducing order with the bounded DOFs taken out and appended: eliminating the
  // others first in their own order fills no more than before, and B's block becomes the
  // dense Schur complement (|B|²/2 entries).
  const int* perm = static_cast<const int*>(plain->Perm);
  std::vector<int> order;
  order.reserve(n);
  for (int k = 0; k < n; ++k)
    if (!is_bounded[perm[k]]) order.push_back(perm[k]);
  for (int k = 0; k < n; ++k)
    if (is_bounded[perm[k]]) order.push_back(perm[k]);
  cholmod_free_factor(&plain, &common_);
  common_.nmethods = 1;
  common_.method[0].ordering = CHOLMOD_GIVEN;
  factor_ = cholmod_analyze_p(&view, order.data(), nullptr, 0, &common_);
  check_cholmod_status(common_, "the symbolic analysis");
  // The postordering keeps B last when its block is a chain at the tree's root (a connected
  // body); otherwise this solver does not apply.
  first_bounded_ = n - static_cast<int>(bounded.size());
  slot_.assign(n, -1);
  const int* final_perm = static_cast<const int*>(factor_->Perm);
  for (int k = first_bounded_; k < n; ++k) {
    if (!is_bounded[final_perm[k]]) return false;
    slot_[final_perm[k]] = k - first_bounded_;
  }
  return true;
}

void BoundedComplementSolver::invert_complement() {
  const int m = static_cast<int>(factor_->n) - first_bounded_;
  // L_BB from the supernodes holding columns ≥ first_bounded_ (column-major dense blocks of
  // nsrow rows; the rows above a column's diagonal are not part of L).
  Eigen::MatrixXd l_bb = Eigen::MatrixXd::Zero(m, m);
  const int* super = static_cast<const int*>(factor_->super);
  const int* pi = static_cast<const int*>(factor_->pi);
  const int* px = static_cast<const int*>(factor_->px);
  const int* rows = static_cast<const int*>(factor_->s);
  const double* x = static_cast<const double*>(factor_->x);
  for (size_t s = 0; s < factor_->nsuper; ++s) {
    const int nsrow = pi[s + 1] - pi[s];
    for (int j = std::max(super[s], first_bounded_); j < super[s + 1]; ++j)
      for (int r = 0; r < nsrow; ++r) {
        const int i = rows[pi[s] + r];
        if (i >= j)
          l_bb(i - first_bounded_, j - first_bounded_) = x[px[s] + (j - super[s]) * nsrow + r];
      }
  }
  const Eigen::MatrixXd l_inverse =
      l_bb.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(m, m));
  complement_inverse_.setZero(m, m);
  complement_inverse_.selfadjointView<Eigen::Lower>().rankUpdate(l_inverse.transpose());
  complement_inverse_ = complement_inverse_.selfadjointView<Eigen::Lower>();
}

Vector BoundedComplementSolver::solve_full(const Vector& b) {
  Vector rhs = b;
  cholmod_dense view{};
  view.nrow = view.d = view.nzmax = static_cast<size_t>(rhs.size());
  view.ncol = 1;
  view.x = rhs.data();
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor_, &view, &common_);
  check_cholmod_status(common_, "the triangular solves");
  Vector out = Eigen::Map<const Vector>(static_cast<const double*>(x->x), b.size());
  cholmod_free_dense(&x, &common_);
  return out;
}

bool BoundedComplementSolver::solve(const std::vector<char>& held, const Vector& b,
                                    const Vector& psi, Vector& x) {
  std::vector<int> dofs, slots;
  for (size_t i = 0; i < held.size(); ++i)
    if (held[i]) {
      if (slot_[i] < 0) return false;
      dofs.push_back(static_cast<int>(i));
      slots.push_back(slot_[i]);
    }
  Vector y = solve_full(b);
  if (dofs.empty()) {
    x = std::move(y);
    return true;
  }
  const Eigen::LLT<Eigen::MatrixXd> g_hh(complement_inverse_(slots, slots));
  if (g_hh.info() != Eigen::Success) return false;
  Vector gap(static_cast<Eigen::Index>(dofs.size()));
  for (size_t h = 0; h < dofs.size(); ++h) gap[h] = y[dofs[h]] - psi[dofs[h]];
  const Vector mu = g_hh.solve(gap);
  Vector z = b;
  for (size_t h = 0; h < dofs.size(); ++h) z[dofs[h]] -= mu[h];
  x = solve_full(z);
  for (const int i : dofs) x[i] = psi[i];
  return true;
}

}  // namespace fosls
