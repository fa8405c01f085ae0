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
std::array<int, 12> triangle_dofs(const FoslsSpace& space, int t);

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
AssemblyPattern assembly_pattern(const FoslsSpace& space, int threads,
                                 const Deadline& deadline = {});

/// Position of entry (row, col) in the values of a compressed column-major `pattern`; the
/// entry must be stored.
inline int entry_position(const SparseMatrix& pattern, int row, int col) {
  const int* inner = pattern.innerIndexPtr();
  const int* begin = inner + pattern.outerIndexPtr()[col];
  const int* end = inner + pattern.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - inner);
}

}  // namespace fosls
