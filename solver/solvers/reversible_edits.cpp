#include "solvers/reversible_edits.hpp"

#include <algorithm>

namespace fosls {

namespace {
/// The stored value at (row, col) of a compressed column-major matrix, or nullptr.
double* stored_entry(SparseMatrix& m, int row, int col) {
  int* first = m.innerIndexPtr() + m.outerIndexPtr()[col];
  int* last = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
  int* at = std::lower_bound(first, last, row);
  if (at == last || *at != row) return nullptr;
  return m.valuePtr() + (at - m.innerIndexPtr());
}
}  // namespace

bool ReversibleEdits::add_within_pattern(const SparseMatrix& c) {
  SparseMatrix& m = *matrix_;
  if (!m.isCompressed() || c.rows() != m.rows() || c.cols() != m.cols()) return false;
  for (int col = 0; col < c.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(c, col); it; ++it)
      if (!stored_entry(m, static_cast<int>(it.row()), col)) return false;
  for (int col = 0; col < c.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(c, col); it; ++it) {
      double* value = stored_entry(m, static_cast<int>(it.row()), col);
      save(value);
      *value += it.value();
    }
  return true;
}

void ReversibleEdits::restore() {
  double* values = matrix_->valuePtr();
  for (auto it = saved_.rbegin(); it != saved_.rend(); ++it) values[it->first] = it->second;
  saved_.clear();
}

}  // namespace fosls
