#include "solvers/truncation_correction.hpp"

#include <algorithm>

namespace fosls {

namespace {

using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
using Triplets = std::vector<Eigen::Triplet<double>>;

/// A small set of indices out of [0, n): a bit per index and the sorted members, so that the
/// position of a member costs a binary search and the set n / 8 bytes (two int maps of the fine
/// size were a fifth of the transient at a solve's peak).
class SparseIndexSet {
 public:
  explicit SparseIndexSet(int n) : in_(n, false) {}
  void insert(int i) {
    if (!in_[i]) in_[i] = true, members_.push_back(i);
  }
  /// Call after the last insert: positions follow the sorted order.
  void finish() { std::sort(members_.begin(), members_.end()); }
  /// Position of i among the members, −1 if it is not one.
  int position(int i) const {
    if (!in_[i]) return -1;
    return static_cast<int>(std::lower_bound(members_.begin(), members_.end(), i) -
                            members_.begin());
  }
  const std::vector<int>& members() const { return members_; }

 private:
  std::vector<bool> in_;
  std::vector<int> members_;
};

/// F = P̃ − P on its nonzero rows: −P on the truncated rows plus the moves, in one pass over P
/// by fine row, then renumbered to F's rows (the members of `f_rows`).
Triplets difference_rows(const SparseMatrix& p, const std::vector<char>& truncated,
                         const SparseMatrix& moves, SparseIndexSet& f_rows) {
  Triplets tf;
  for (int col = 0; col < p.cols(); ++col) {
    for (SparseMatrix::InnerIterator it(p, col); it; ++it)
      if (truncated[it.row()]) {
        f_rows.insert(static_cast<int>(it.row()));
        tf.emplace_back(static_cast<int>(it.row()), col, -it.value());
      }
    for (SparseMatrix::InnerIterator it(moves, col); it; ++it) {
      f_rows.insert(static_cast<int>(it.row()));
      tf.emplace_back(static_cast<int>(it.row()), col, it.value());
    }
  }
  f_rows.finish();
  for (auto& t : tf) t = Eigen::Triplet<double>(f_rows.position(t.row()), t.col(), t.value());
  return tf;
}

/// The rows of P that A couples to `rows`, in a small row-major matrix (row k: the k-th member
/// of `coupled`).
RowMajorMatrix coupled_rows(const SparseMatrix& a, const SparseMatrix& p,
                            const std::vector<int>& rows, SparseIndexSet& coupled) {
  for (int row : rows)
    for (SparseMatrix::InnerIterator it(a, row); it; ++it)
      coupled.insert(static_cast<int>(it.row()));
  coupled.finish();
  Triplets tp;
  for (int col = 0; col < p.cols(); ++col)
    for (SparseMatrix::InnerIterator it(p, col); it; ++it)
      if (const int c = coupled.position(it.row()); c >= 0) tp.emplace_back(c, col, it.value());
  RowMajorMatrix p_rows(static_cast<int>(coupled.members().size()), p.cols());
  p_rows.setFromTriplets(tp.begin(), tp.end());
  return p_rows;
}

}  // namespace

void truncation_correction(const SparseMatrix& A, const SparseMatrix& P,
                           const std::vector<char>& truncated, const SparseMatrix& moves,
                           SparseMatrix& out) {
  // P̃ = P + F where F, the difference made by truncation, has few rows (the contact
  // boundary and the fine edges that carry moved flux), so
  //   P̃ᵀAP̃ = PᵀAP + FᵀAP + (FᵀAP)ᵀ + FᵀAF,
  // where PᵀAP and AP are computed once: the fine-level product is not redone for every new
  // active set. Only F's rows, and the rows of P that A couples to them, are formed (not F or a
  // row-major P of the fine size).
  const int n = static_cast<int>(P.rows()), nc = static_cast<int>(P.cols());
  SparseIndexSet f_rows(n);
  const Triplets tf = difference_rows(P, truncated, moves, f_rows);
  const std::vector<int>& rows = f_rows.members();
  const int m = static_cast<int>(rows.size());
  if (m == 0) {
    out = SparseMatrix(nc, nc);
    out.makeCompressed();
    return;
  }
  SparseIndexSet coupled(n);
  const RowMajorMatrix p_rows = coupled_rows(A, P, rows, coupled);
  // Rows `rows` of A P: row k of A is its column k (A is symmetric), times the rows of P, each
  // row summed in a dense accumulator first (one entry per coarse column it reaches, not one
  // per product); and A on F's rows and columns.
  Triplets tap, taa;
  Vector sum = Vector::Zero(nc);
  std::vector<int> reached;
  for (int k = 0; k < m; ++k) {
    for (SparseMatrix::InnerIterator it(A, rows[k]); it; ++it) {
      for (RowMajorMatrix::InnerIterator pt(p_rows, coupled.position(it.row())); pt; ++pt) {
        const int col = static_cast<int>(pt.col());
        if (sum[col] == 0.0) reached.push_back(col);
        sum[col] += it.value() * pt.value();
      }
      if (const int l = f_rows.position(it.row()); l >= 0) taa.emplace_back(l, k, it.value());
    }
    for (int col : reached) tap.emplace_back(k, col, sum[col]), sum[col] = 0.0;
    reached.clear();
  }
  SparseMatrix rf(m, nc), rap(m, nc), aff(m, m);
  rf.setFromTriplets(tf.begin(), tf.end());
  rap.setFromTriplets(tap.begin(), tap.end());
  aff.setFromTriplets(taa.begin(), taa.end());
  const SparseMatrix rft = rf.transpose();
  const SparseMatrix cross = rft * rap;  // FᵀAP
  const SparseMatrix inner = rft * (aff * rf);
  out = cross + SparseMatrix(cross.transpose()) + inner;
  out.makeCompressed();
}

}  // namespace fosls
