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
  /// P̃ given as a matrix; with `p`, the P it was truncated from, a column that keeps only a
  /// negligible part of P's (below) is removed.
  static TruncatedProlongation formed(SparseMatrix p_tilde, const SparseMatrix* p = nullptr);
  /// P̃ = P without the rows i with dropped[i] (empty: none), plus `moves`, and without the
  /// columns that keep only a negligible part of P's (below); P must outlive this.
  static TruncatedProlongation applied(const SparseMatrix& p, std::vector<char> dropped,
                                       SparseMatrix moves);

  /// A coarse function whose largest entry left after truncation is at most this fraction of
  /// its largest entry in P is truncated away entirely. Under bisection a coarse U_n whose fine
  /// U_n are all truncated keeps only its leakage into the fine tangential components, the sine
  /// of the angle between the two levels' normals at a vertex, which is 10⁻⁵ where only a
  /// neighbouring face was bisected: the level's matrix then has a diagonal entry 10⁻¹⁰ of its
  /// neighbours' and its vertex patch is not definite in floating point
  /// (docs/performance.md, "3D: uniform against adaptive").
  static constexpr double kNegligibleColumn = 1e-3;

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
        if (!p_ || kept(static_cast<int>(it.row()), col))
          visit(static_cast<int>(it.row()), col, it.value());
    if (p_)
      for (int col = 0; col < moves_.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(moves_, col); it; ++it)
          if (live(col)) visit(static_cast<int>(it.row()), col, it.value());
  }
  /// vanished[J]: column J of P̃ is empty (the coarse function was truncated away entirely).
  std::vector<char> vanished_columns() const;

 private:
  bool kept(int row) const { return dropped_.empty() || !dropped_[row]; }
  bool live(int col) const { return negligible_.empty() || !negligible_[col]; }
  bool kept(int row, int col) const { return kept(row) && live(col); }

  SparseMatrix formed_;
  const SparseMatrix* p_ = nullptr;
  std::vector<char> dropped_;
  std::vector<char> negligible_;  ///< columns of an applied P̃ removed as negligible
  SparseMatrix moves_;
};

}  // namespace fosls
