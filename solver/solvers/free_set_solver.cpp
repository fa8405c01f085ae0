#include "solvers/free_set_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>

#include "core/indefinite_system.hpp"
#include "solvers/cholmod_checks.hpp"

namespace fosls {

namespace {

constexpr const char* kIndefinite = "the coarse-level matrix is not positive definite";

/// r_F − A_FH d_H on the free DOFs (the held DOFs' pull on the free ones); 0 on the held ones.
Vector free_right_hand_side(const SparseMatrix& A, const std::vector<signed char>& state,
                            const Vector& r, const Vector& d) {
  const int n = static_cast<int>(r.size());
  Vector ad = Vector::Zero(n);
  for (int j = 0; j < n; ++j)
    if (state[j] != 0 && d[j] != 0.0)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it) ad[it.row()] += it.value() * d[j];
  Vector rhs(n);
  for (int i = 0; i < n; ++i) rhs[i] = state[i] == 0 ? r[i] - ad[i] : 0.0;
  return rhs;
}

bool same_pattern(const SparseMatrix& a, const SparseMatrix& b) {
  if (!a.isCompressed() || !b.isCompressed() || a.rows() != b.rows() ||
      a.nonZeros() != b.nonZeros())
    return false;
  const int n = static_cast<int>(a.outerSize());
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + n + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
}

/// The free block gathered and factorised by Eigen's simplicial LDLᵀ with its own ordering.
class ReducedSolver : public FreeSetSolver {
 public:
  explicit ReducedSolver(const SparseMatrix& A) : A_(A) {
    full_.compute(A_);
    bool ok = full_.info() == Eigen::Success;
    if (ok)
      for (int i = 0; i < full_.vectorD().size(); ++i) ok &= full_.vectorD()[i] > 0;
    if (!ok) throw IndefiniteSystemError(kIndefinite);
  }

  bool solve(const std::vector<signed char>& state, const Vector& r, const Vector& d,
             Vector& y) override {
    const int n = static_cast<int>(r.size());
    std::vector<int> free;
    std::vector<int> index(n, -1);
    for (int i = 0; i < n; ++i)
      if (state[i] == 0) index[i] = static_cast<int>(free.size()), free.push_back(i);
    y = d;
    if (free.empty()) return true;
    if (static_cast<int>(free.size()) == n) {
      y = full_.solve(r);
      return true;
    }
    const Vector all = free_right_hand_side(A_, state, r, d);
    const int m = static_cast<int>(free.size());
    Vector rhs(m);
    for (int a = 0; a < m; ++a) rhs[a] = all[free[a]];
    // The same free set comes back call after call once the active set has settled (the
    // linear phase): keep the factorisation of the last one.
    if (last_free_ != free && !factorise(free, index)) return false;
    Vector sol = last_.solve(rhs);
    for (int a = 0; a < m; ++a) y[free[a]] = sol[a];
    return true;
  }

 private:
  bool factorise(const std::vector<int>& free, const std::vector<int>& index) {
    const int m = static_cast<int>(free.size());
    std::vector<Eigen::Triplet<double>> t;
    for (int a = 0; a < m; ++a)
      for (SparseMatrix::InnerIterator it(A_, free[a]); it; ++it)
        if (index[it.row()] >= 0) t.emplace_back(index[it.row()], a, it.value());
    SparseMatrix aff(m, m);
    aff.setFromTriplets(t.begin(), t.end());
    last_.compute(aff);
    last_free_ = free;
    if (last_.info() == Eigen::Success) return true;
    last_free_.clear();
    return false;
  }

  SparseMatrix A_;
  Eigen::SimplicialLDLT<SparseMatrix> full_;
  Eigen::SimplicialLDLT<SparseMatrix> last_;
  std::vector<int> last_free_;  ///< the free set `last_` factorises
};

/// The whole pattern analysed once; a held DOF's row and column reduced to their diagonal.
class HeldRowsSolver : public FreeSetSolver {
 public:
  explicit HeldRowsSolver(const SparseMatrix& A) : A_(A), held_matrix_(A) {
    if (!compute_checked(full_, A_)) throw IndefiniteSystemError(kIndefinite);
    analyse_checked(held_, held_matrix_);
  }

  bool refactor(const SparseMatrix& A) override {
    if (!same_pattern(A, A_)) return false;
    last_free_.clear();  // first: `held_` holds the old values' factor from here on
    std::copy(A.valuePtr(), A.valuePtr() + A.nonZeros(), A_.valuePtr());
    if (!factorize_checked(full_, A_)) throw IndefiniteSystemError(kIndefinite);
    return true;
  }

  bool solve(const std::vector<signed char>& state, const Vector& r, const Vector& d,
             Vector& y) override {
    const int n = static_cast<int>(r.size());
    y = d;
    int num_free = 0;
    for (int i = 0; i < n; ++i) num_free += state[i] == 0;
    if (num_free == 0) return true;
    if (num_free == n) {
      y = solve_checked(full_, r);
      return true;
    }
    std::vector<char> free(n);
    for (int i = 0; i < n; ++i) free[i] = state[i] == 0;
    if (last_free_ != free && !factorise(free)) return false;
    const Vector sol = solve_checked(held_, free_right_hand_side(A_, state, r, d));
    for (int i = 0; i < n; ++i)
      if (state[i] == 0) y[i] = sol[i];
    return true;
  }

 private:
  bool factorise(const std::vector<char>& free) {
    const double* a = A_.valuePtr();
    double* h = held_matrix_.valuePtr();
    for (int j = 0; j < A_.outerSize(); ++j)
      for (int k = A_.outerIndexPtr()[j]; k < A_.outerIndexPtr()[j + 1]; ++k) {
        const int i = A_.innerIndexPtr()[k];
        h[k] = (free[i] && free[j]) || i == j ? a[k] : 0.0;
      }
    last_free_.clear();  // first: a throw below leaves no stale claim on `held_`
    const bool definite = factorize_checked(held_, held_matrix_);
    last_free_ = free;
    if (definite) return true;
    last_free_.clear();
    return false;
  }

  SparseMatrix A_;
  SparseMatrix held_matrix_;  ///< A's pattern, with the held rows and columns' values
  Eigen::CholmodSupernodalLLT<SparseMatrix> full_;
  Eigen::CholmodSupernodalLLT<SparseMatrix> held_;
  std::vector<char> last_free_;  ///< the free set `held_` factorises
};

}  // namespace

std::unique_ptr<FreeSetSolver> FreeSetSolver::make(const SparseMatrix& A, BlockFactorization kind) {
  if (kind == BlockFactorization::held_rows) return std::make_unique<HeldRowsSolver>(A);
  return std::make_unique<ReducedSolver>(A);
}

}  // namespace fosls
