#pragma once
// The linear solve inside the sparse box-QP solver (solvers/exact_box_qp.hpp): the minimiser
// of ½ yᵀ A y − rᵀ y over a free set of DOFs, the others held at given values. Active-set
// methods ask for it once per active set, and the free set changes between calls by a few DOFs.
// Two factorisations of the same solve (core/level_hierarchy.hpp, BlockFactorization):
//  - reduced: the free block is gathered and factorised anew, with its own ordering, whenever
//    the free set changes — cheap for the thin blocks of 2D;
//  - held_rows: the whole matrix's pattern is ordered and analysed once (CHOLMOD, supernodal),
//    and a held DOF's row and column keep only their diagonal entry, which leaves the free block
//    and the held values as the solution; a new free set costs one numeric factorisation of a
//    fixed pattern — for the slab-shaped blocks of 3D, whose reduced factorisations were most
//    of a solve (docs/performance.md, "3D").

#include <memory>
#include <vector>

#include "core/box_qp.hpp"
#include "core/level_hierarchy.hpp"

namespace fosls {

class FreeSetSolver {
 public:
  /// Throws IndefiniteSystemError when A is not positive definite.
  static std::unique_ptr<FreeSetSolver> make(const SparseMatrix& A, BlockFactorization kind);
  virtual ~FreeSetSolver() = default;

  /// state: 0 free, anything else held at its value in d. y: d on the held DOFs, the minimiser
  /// on the free ones. False when the free block is not definite. Keeps the factorisation of the
  /// last free set (a cache, which changes no result).
  virtual bool solve(const std::vector<signed char>& state, const Vector& r, const Vector& d,
                     Vector& y) = 0;

  /// The same solver for a matrix of A's pattern with new values, keeping what was computed
  /// from the pattern alone (held_rows: the ordering and symbolic analysis). False, with nothing
  /// changed, when the kind keeps nothing or the pattern differs; throws IndefiniteSystemError
  /// as make does.
  virtual bool refactor(const SparseMatrix& A) {
    (void)A;
    return false;
  }
};

}  // namespace fosls
