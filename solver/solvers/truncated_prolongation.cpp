#include "solvers/truncated_prolongation.hpp"

namespace fosls {

TruncatedProlongation TruncatedProlongation::formed(SparseMatrix p_tilde) {
  TruncatedProlongation t;
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
    if (c[col] == 0.0) continue;
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
        if (it.value() != 0.0 && (all_rows || kept(static_cast<int>(it.row())))) vanished[col] = 0;
  };
  if (!p_) {
    mark(formed_, true);
  } else {
    mark(*p_, false);
    mark(moves_, true);
  }
  return vanished;
}

}  // namespace fosls
