#pragma once
// Pattern-first assembly: the sparsity of the FOSLS matrix follows from the mesh
// topology alone, so it is computed once, the values are written into it in place and no
// triplet lists are kept (they were the assembly's peak: docs/performance.md, "Assembly").

#include <algorithm>
#include <array>
#include <vector>

#include "core/box_qp.hpp"
#include "core/deadline.hpp"
#include "fem/fosls_space.hpp"

namespace fosls {

/// The 12 local DOFs of triangle t (u: 2k + c, σ: 6 + 2k + i) in the space's full numbering.
std::array<int, 12> triangle_dofs(const FoslsSpace<2>& space, int t);

/// Which triangles each thread of a parallel assembly visits. Thread t owns the columns (and
/// the right-hand side entries) of the free DOFs whose lowest-numbered triangle lies in its
/// range [range_begin[t], range_begin[t + 1]), and visits, in increasing order, every triangle
/// that holds one of them or lies in its range. Every matrix entry is therefore summed by one
/// thread in triangle order: the same sums, bit for bit, whatever the number of threads, with
/// no locks and only the triangles along the range boundaries computed twice.
struct AssemblyPartition {
  std::vector<int> range_begin;             ///< threads + 1 entries
  std::vector<int> owner;                   ///< per free DOF: the thread that writes its column
  std::vector<std::vector<int>> triangles;  ///< per thread, increasing
};

/// The matrix of the free DOFs with a stored (zero) entry wherever two free DOFs share a
/// triangle, column-major with sorted rows, and the partition of its assembly over `threads`.
struct AssemblyPattern {
  SparseMatrix matrix;
  AssemblyPartition partition;
};
/// Throws TimeLimitReached between its passes once `deadline` has passed.
AssemblyPattern assembly_pattern(const FoslsSpace<2>& space, int threads,
                                 const Deadline& deadline = {});

/// The matrix of `n` free DOFs with a stored (zero) entry wherever two free DOFs share a cell,
/// compressed column-major with sorted rows, for spaces whose cells are not FoslsSpace's
/// triangles (order 2, tetrahedra): `free_dofs(c)` gives cell c's DOFs as free indices, −1 for
/// fixed ones. Values are then added in place (entry_position), with no triplet list.
template <class FreeDofs>
SparseMatrix cell_pattern(int n, int cells, const FreeDofs& free_dofs) {
  std::vector<int> start(n + 1, 0);
  for (int c = 0; c < cells; ++c)
    for (int f : free_dofs(c))
      if (f >= 0) ++start[f + 1];
  for (int f = 0; f < n; ++f) start[f + 1] += start[f];
  std::vector<int> cells_of(start[n]), next(start.begin(), start.end() - 1);
  for (int c = 0; c < cells; ++c)
    for (int f : free_dofs(c))
      if (f >= 0) cells_of[next[f]++] = c;
  std::vector<int> outer(n + 1, 0), inner, marker(n, -1);
  for (int col = 0; col < n; ++col) {
    const std::size_t first = inner.size();
    for (int k = start[col]; k < start[col + 1]; ++k)
      for (int row : free_dofs(cells_of[k]))
        if (row >= 0 && marker[row] != col) marker[row] = col, inner.push_back(row);
    std::sort(inner.begin() + first, inner.end());
    outer[col + 1] = static_cast<int>(inner.size());
  }
  std::vector<double> zeros(inner.size(), 0.0);
  return Eigen::Map<const SparseMatrix>(n, n, static_cast<int>(inner.size()), outer.data(),
                                        inner.data(), zeros.data());
}

/// Position of entry (row, col) in the values of a compressed column-major `pattern`; the
/// entry must be stored.
inline int entry_position(const SparseMatrix& pattern, int row, int col) {
  const int* inner = pattern.innerIndexPtr();
  const int* begin = inner + pattern.outerIndexPtr()[col];
  const int* end = inner + pattern.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - inner);
}

}  // namespace fosls
