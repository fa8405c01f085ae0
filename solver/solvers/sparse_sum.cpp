#include "solvers/sparse_sum.hpp"

#include "core/fosls_assert.hpp"

namespace fosls {

namespace {
/// Walks column `col` of a (without dropped rows) and of b in row order, calling
/// `emit(row, value)` once per row present in either.
template <class Emit>
void merge_column(const SparseMatrix& a, const SparseMatrix& b, int col,
                  const std::vector<char>* dropped_rows, Emit emit) {
  SparseMatrix::InnerIterator ia(a, col), ib(b, col);
  auto skip_dropped = [&] {
    while (dropped_rows && ia && (*dropped_rows)[ia.row()]) ++ia;
  };
  skip_dropped();
  while (ia || ib) {
    if (ib && (!ia || ib.row() < ia.row())) {
      emit(static_cast<int>(ib.row()), ib.value());
      ++ib;
    } else if (ia && (!ib || ia.row() < ib.row())) {
      emit(static_cast<int>(ia.row()), ia.value());
      ++ia;
      skip_dropped();
    } else {
      emit(static_cast<int>(ia.row()), ia.value() + ib.value());
      ++ia, ++ib;
      skip_dropped();
    }
  }
}
}  // namespace

SparseMatrix sparse_sum(const SparseMatrix& a, const SparseMatrix& b,
                        const std::vector<char>* dropped_rows) {
  FOSLS_ASSERT(a.rows() == b.rows() && a.cols() == b.cols(), "sparse_sum: shapes differ");
  FOSLS_ASSERT(a.isCompressed() && b.isCompressed(), "sparse_sum: uncompressed operand");
  const int cols = static_cast<int>(a.cols());
  SparseMatrix out(a.rows(), a.cols());
  int* outer = out.outerIndexPtr();
  outer[0] = 0;
  for (int col = 0; col < cols; ++col) {
    int count = 0;
    merge_column(a, b, col, dropped_rows, [&count](int, double) { ++count; });
    outer[col + 1] = outer[col] + count;
  }
  out.resizeNonZeros(outer[cols]);
  int* rows = out.innerIndexPtr();
  double* values = out.valuePtr();
  for (int col = 0; col < cols; ++col) {
    int at = outer[col];
    merge_column(a, b, col, dropped_rows, [&](int row, double value) {
      rows[at] = row;
      values[at++] = value;
    });
  }
  return out;
}

}  // namespace fosls
