#pragma once
// The truncated prolongation P̃ of a level (docs/method.md §4.2): P without the rows of the
// level's truncated DOFs, plus the few flux moves that keep coarse contact functions'
// divergence bounded. On coarse levels it is formed as a matrix (the Galerkin product of the
// next level needs it); on the finest it is applied from P, the truncated set and the moves,
// since there it would be a near-copy of the largest transfer (docs/performance.md, "Measurements
// behind choices in the code").

#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

class TruncatedProlongation {
 public:
  TruncatedProlongation() = default;
  /// P̃ given as a matrix.
  static TruncatedProlongation formed(SparseMatrix p_tilde);
  /// P̃ = P without the rows i with dropped[i] (empty: none), plus `moves`; P must outlive
  /// this.
  static TruncatedProlongation applied(const SparseMatrix& p, std::vector<char> dropped,
                                       SparseMatrix moves);

  /// The matrix, when formed; nullptr otherwise.
  const SparseMatrix* matrix() const { return p_ ? nullptr : &formed_; }
  /// The flux moves of an applied P̃.
  const SparseMatrix& moves() const { return moves_; }
  int cols() const { return static_cast<int>(p_ ? p_->cols() : formed_.cols()); }

  /// rc = P̃ᵀ r.
  void restrict_to(const Vector& r, Vector& rc) const;
  /// v = P̃ c.
  void prolongate(const Vector& c, Vector& v) const;
  /// visit(row, col, value) for every stored entry of P̃ (an entry of P and one of a move at the
  /// same place are visited apart).
  template <class Visit>
  void for_each_entry(Visit visit) const {
    const SparseMatrix& m = p_ ? *p_ : formed_;
    for (int col = 0; col < m.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(m, col); it; ++it)
        if (!p_ || kept(static_cast<int>(it.row())))
          visit(static_cast<int>(it.row()), col, it.value());
    if (p_)
      for (int col = 0; col < moves_.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(moves_, col); it; ++it)
          visit(static_cast<int>(it.row()), col, it.value());
  }
  /// vanished[J]: column J of P̃ is empty (the coarse function was truncated away entirely).
  std::vector<char> vanished_columns() const;

 private:
  bool kept(int row) const { return dropped_.empty() || !dropped_[row]; }

  SparseMatrix formed_;
  const SparseMatrix* p_ = nullptr;
  std::vector<char> dropped_;
  SparseMatrix moves_;
};

}  // namespace fosls
