#pragma once
// Pattern-first assembly, the one local-to-global scatter of every space (P1–RT0 in 2D and 3D,
// order 2): the sparsity of the FOSLS matrix follows from the mesh topology alone, so it is
// computed once, the cells' local systems are added into it in place, in parallel and under a
// deadline, and no triplet lists are kept (they were the assembly's peak:
// docs/performance.md, "Assembly").
//
// A Space here is FoslsSpace<2>, FoslsSpace<3> or P2Rt1Space: kCellDofs, cell_dofs(t) in its
// full numbering, free_index(dof), num_free() and mesh().num_cells().

#include <Eigen/Core>
#include <algorithm>
#include <functional>
#include <vector>

#include "core/box_qp.hpp"
#include "core/deadline.hpp"

namespace fosls {

/// Which cells each thread of a parallel assembly visits. Thread t owns the columns (and the
/// right-hand side entries) of the free DOFs whose lowest-numbered cell lies in its range
/// [range_begin[t], range_begin[t + 1]), and visits, in increasing order, every cell that holds
/// one of them or lies in its range. Every matrix entry is therefore summed by one thread in
/// cell order: the same sums, bit for bit, whatever the number of threads, with no locks and
/// only the cells along the range boundaries computed twice.
struct AssemblyPartition {
  std::vector<int> range_begin;         ///< threads + 1 entries
  std::vector<int> owner;               ///< per free DOF: the thread that writes its column
  std::vector<std::vector<int>> cells;  ///< per thread, increasing
  int threads() const { return static_cast<int>(range_begin.size()) - 1; }
};

/// The matrix of the free DOFs with a stored (zero) entry wherever two free DOFs share a cell,
/// column-major with sorted rows, and the partition of its assembly over `threads`.
struct AssemblyPattern {
  SparseMatrix matrix;
  AssemblyPartition partition;
};

/// Throws TimeLimitReached between its passes once `deadline` has passed.
template <class Space>
AssemblyPattern assembly_pattern(const Space& space, int threads, const Deadline& deadline = {});

/// One cell's terms of J = ½ xᵀKx − bᵀx + c on its local DOFs (cell_dofs order, rotated).
template <int n>
struct LocalSystem {
  Eigen::Matrix<double, n, n> K;
  Eigen::Matrix<double, n, 1> b;
  double c = 0.0;
};

/// How the constant of J, whose sum over the cells is the one sum the partition cannot keep in
/// cell order, is added up: kPerThread in each thread's cells' order, then thread by thread
/// (cheapest; its last bits depend on the number of threads), kCellOrder cell by cell in cell
/// order (the same on any number of threads). The lowest order keeps kPerThread and order 2
/// kCellOrder, each the sum it had before they shared this scatter, so their results stay bit
/// for bit.
enum class ConstantSum { kPerThread, kCellOrder };

/// Adds every cell's local system, computed by `local(t, system)`, into the pattern's matrix
/// and b (the fixed DOFs' couplings, with values xd, moved to b) on the pattern's threads;
/// returns J's constant. Polls `deadline` and throws TimeLimitReached once it has passed.
template <class Space>
double scatter_local_systems(const Space& space, AssemblyPattern& pattern, const Vector& xd,
                             Vector& b,
                             const std::function<void(int, LocalSystem<Space::kCellDofs>&)>& local,
                             ConstantSum sum, const Deadline& deadline = {});

/// Position of entry (row, col) in the values of a compressed column-major `pattern`; the
/// entry must be stored.
inline int entry_position(const SparseMatrix& pattern, int row, int col) {
  const int* inner = pattern.innerIndexPtr();
  const int* begin = inner + pattern.outerIndexPtr()[col];
  const int* end = inner + pattern.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - inner);
}

}  // namespace fosls
