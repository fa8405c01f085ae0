#include "solvers/truncated_prolongation.hpp"

#include <algorithm>
#include <cmath>

namespace fosls {

namespace {

/// The largest magnitude in each column of m.
std::vector<double> column_max(const SparseMatrix& m) {
  std::vector<double> largest(m.cols(), 0.0);
  for (int col = 0; col < m.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(m, col); it; ++it)
      largest[col] = std::max(largest[col], std::abs(it.value()));
  return largest;
}

/// The columns of P̃ whose largest entry is at most kNegligibleColumn times P's (and not 0:
/// an empty column is vanished already). `kept_max` holds P̃'s largest entry per column.
std::vector<char> negligible_columns(const SparseMatrix& p, const std::vector<double>& kept_max) {
  const std::vector<double> all = column_max(p);
  std::vector<char> negligible(p.cols(), 0);
  bool any = false;
  for (int col = 0; col < p.outerSize(); ++col) {
    const double kept = kept_max[col];
    if (kept > 0.0 && kept <= TruncatedProlongation::kNegligibleColumn * all[col])
      negligible[col] = 1, any = true;
  }
  if (!any) negligible.clear();
  return negligible;
}

}  // namespace

TruncatedProlongation TruncatedProlongation::formed(SparseMatrix p_tilde, const SparseMatrix* p) {
  TruncatedProlongation t;
  if (p) {
    const std::vector<char> negligible = negligible_columns(*p, column_max(p_tilde));
    if (!negligible.empty()) {
      p_tilde.prune([&](int, int col, double) { return !negligible[col]; });
      p_tilde.makeCompressed();
    }
  }
  t.formed_.swap(p_tilde);
  return t;
}

TruncatedProlongation TruncatedProlongation::applied(const SparseMatrix& p,
                                                     std::vector<char> dropped,
                                                     SparseMatrix moves) {
  TruncatedProlongation t;
  t.p_ = &p;
  t.dropped_ = std::move(dropped);
  t.moves_.swap(moves);
  if (!t.dropped_.empty()) {
    std::vector<double> kept_max = column_max(t.moves_);
    for (int col = 0; col < p.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(p, col); it; ++it)
        if (t.kept(static_cast<int>(it.row())))
          kept_max[col] = std::max(kept_max[col], std::abs(it.value()));
    t.negligible_ = negligible_columns(p, kept_max);
  }
  return t;
}

void TruncatedProlongation::restrict_to(const Vector& r, Vector& rc) const {
  if (!p_) {
    rc = formed_.transpose() * r;
    return;
  }
  const int nc = cols();
  rc.resize(nc);
  // Column by column: each coarse entry is one dot product, so the columns split over threads.
#pragma omp parallel for schedule(static)
  for (int col = 0; col < nc; ++col) {
    double s = 0.0;
    if (!live(col)) {
      rc[col] = 0.0;
      continue;
    }
    for (SparseMatrix::InnerIterator it(*p_, col); it; ++it)
      if (kept(static_cast<int>(it.row()))) s += it.value() * r[it.row()];
    for (SparseMatrix::InnerIterator it(moves_, col); it; ++it) s += it.value() * r[it.row()];
    rc[col] = s;
  }
}

void TruncatedProlongation::prolongate(const Vector& c, Vector& v) const {
  if (!p_) {
    v = formed_ * c;
    return;
  }
  v.setZero(p_->rows());
  for (int col = 0; col < cols(); ++col) {
    if (c[col] == 0.0 || !live(col)) continue;
    for (SparseMatrix::InnerIterator it(*p_, col); it; ++it)
      if (kept(static_cast<int>(it.row()))) v[it.row()] += it.value() * c[col];
    for (SparseMatrix::InnerIterator it(moves_, col); it; ++it) v[it.row()] += it.value() * c[col];
  }
}

std::vector<char> TruncatedProlongation::vanished_columns() const {
  std::vector<char> vanished(cols(), 1);
  auto mark = [&](const SparseMatrix& m, bool all_rows) {
    for (int col = 0; col < m.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(m, col); it; ++it)
        if (it.value() != 0.0 && (all_rows || kept(static_cast<int>(it.row()), col)))
          vanished[col] = 0;
  };
  if (!p_) {
    mark(formed_, true);
  } else {
    mark(*p_, false);
    mark(moves_, true);
    for (std::size_t col = 0; col < negligible_.size(); ++col)
      if (negligible_[col]) vanished[col] = 1;
  }
  return vanished;
}

}  // namespace fosls
