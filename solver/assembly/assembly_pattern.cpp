#include "assembly/assembly_pattern.hpp"

#include <omp.h>

#include <array>
#include <atomic>
#include <string>

#include "fem/fosls_space.hpp"
#include "fem/p2_rt1_space.hpp"

namespace fosls {

namespace {

const std::string kStage = "assembling the finest level";

/// Free DOF → cells holding it (CSR, cells increasing).
struct DofCells {
  std::vector<int> offset, cells;
};

template <class Space>
DofCells dof_cells(const Space& space) {
  const int n = space.num_free(), nc = space.mesh().num_cells();
  DofCells out;
  out.offset.assign(n + 1, 0);
  for (int t = 0; t < nc; ++t)
    for (int d : space.cell_dofs(t))
      if (const int f = space.free_index(d); f >= 0) ++out.offset[f + 1];
  for (int f = 0; f < n; ++f) out.offset[f + 1] += out.offset[f];
  out.cells.resize(out.offset[n]);
  std::vector<int> next(out.offset.begin(), out.offset.end() - 1);
  for (int t = 0; t < nc; ++t)
    for (int d : space.cell_dofs(t))
      if (const int f = space.free_index(d); f >= 0) out.cells[next[f]++] = t;
  return out;
}

/// The compressed columns of the pattern: column f holds the free DOFs of the cells around f,
/// counted first, then filled.
template <class Space>
void fill_columns(const Space& space, const DofCells& dc, SparseMatrix& a,
                  const Deadline& deadline) {
  const int n = space.num_free();
  // Each pass over the mesh takes as long as a part of the element loop: checked between them,
  // and in the column passes every so many columns (an OpenMP loop cannot be left: the columns
  // after the deadline are skipped, and the check after the pass throws).
  std::atomic<bool> late{false};
  auto out_of_time = [&](int f) {
    if (deadline.is_set() && f % Deadline::kPollEvery == 0 && deadline.passed())
      late.store(true, std::memory_order_relaxed);
    return late.load(std::memory_order_relaxed);
  };
  auto column = [&](int f, std::vector<int>& mark, std::vector<int>& rows) {
    rows.clear();
    for (int k = dc.offset[f]; k < dc.offset[f + 1]; ++k)
      for (int d : space.cell_dofs(dc.cells[k]))
        if (const int g = space.free_index(d); g >= 0 && mark[g] != f)
          mark[g] = f, rows.push_back(g);
  };
  std::vector<int> outer(n + 1, 0);
#pragma omp parallel
  {
    std::vector<int> mark(n, -1), rows;
#pragma omp for schedule(static)
    for (int f = 0; f < n; ++f) {
      if (out_of_time(f)) continue;
      column(f, mark, rows);
      outer[f + 1] = static_cast<int>(rows.size());
    }
  }
  for (int f = 0; f < n; ++f) outer[f + 1] += outer[f];
  deadline.check(kStage);
  a.resize(n, n);
  a.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), a.outerIndexPtr());
  std::fill(a.valuePtr(), a.valuePtr() + outer[n], 0.0);
  deadline.check(kStage);
#pragma omp parallel
  {
    std::vector<int> mark(n, -1), rows;
#pragma omp for schedule(static)
    for (int f = 0; f < n; ++f) {
      if (out_of_time(f)) continue;
      column(f, mark, rows);
      std::sort(rows.begin(), rows.end());
      std::copy(rows.begin(), rows.end(), a.innerIndexPtr() + outer[f]);
    }
  }
  deadline.check(kStage);
}

template <class Space>
AssemblyPartition partition_cells(const Space& space, const DofCells& dc, int threads) {
  const int n = space.num_free(), nc = space.mesh().num_cells();
  AssemblyPartition p;
  threads = std::max(1, threads);
  p.range_begin.resize(threads + 1);
  for (int t = 0; t <= threads; ++t)
    p.range_begin[t] = static_cast<int>(static_cast<long long>(nc) * t / threads);
  auto range_of = [&p, threads](int cell) {
    return static_cast<int>(std::upper_bound(p.range_begin.begin(), p.range_begin.end() - 1, cell) -
                            p.range_begin.begin()) -
           1;
  };
  p.owner.resize(n);
  for (int f = 0; f < n; ++f) p.owner[f] = range_of(dc.cells[dc.offset[f]]);
  p.cells.assign(threads, {});
  std::vector<char> visits(threads);
  for (int t = 0; t < nc; ++t) {
    std::fill(visits.begin(), visits.end(), 0);
    visits[range_of(t)] = 1;
    for (int d : space.cell_dofs(t))
      if (const int f = space.free_index(d); f >= 0) visits[p.owner[f]] = 1;
    for (int k = 0; k < threads; ++k)
      if (visits[k]) p.cells[k].push_back(t);
  }
  return p;
}

}  // namespace

template <class Space>
AssemblyPattern assembly_pattern(const Space& space, int threads, const Deadline& deadline) {
  const DofCells dc = dof_cells(space);
  deadline.check(kStage);
  AssemblyPattern out;
  fill_columns(space, dc, out.matrix, deadline);
  out.partition = partition_cells(space, dc, threads);
  return out;
}

template <class Space>
double scatter_local_systems(const Space& space, AssemblyPattern& pattern, const Vector& xd,
                             Vector& b,
                             const std::function<void(int, LocalSystem<Space::kCellDofs>&)>& local,
                             ConstantSum sum, const Deadline& deadline) {
  constexpr int n = Space::kCellDofs;
  SparseMatrix& a = pattern.matrix;
  const AssemblyPartition& part = pattern.partition;
  const int threads = part.threads();
  double* values = a.valuePtr();
  std::vector<double> per_thread(threads, 0.0);
  std::vector<double> per_cell(sum == ConstantSum::kCellOrder ? space.mesh().num_cells() : 0);
  // An exception cannot leave the parallel region: a thread that sees the deadline passed
  // stops every thread's loop, and the throw comes after the region.
  std::atomic<bool> out_of_time{false};
#pragma omp parallel num_threads(threads)
  // Each part once, also when the runtime gives fewer threads than asked for.
  for (int tid = omp_get_thread_num(); tid < threads; tid += omp_get_num_threads()) {
    LocalSystem<n> loc;
    int polled = 0;
    for (int t : part.cells[tid]) {
      if (deadline.is_set() && ++polled % Deadline::kPollEvery == 0 &&
          (out_of_time.load(std::memory_order_relaxed) || deadline.passed())) {
        out_of_time.store(true, std::memory_order_relaxed);
        break;
      }
      local(t, loc);
      const auto dofs = space.cell_dofs(t);
      std::array<int, n> free;
      for (int i = 0; i < n; ++i) free[i] = space.free_index(dofs[i]);
      const bool in_range = t >= part.range_begin[tid] && t < part.range_begin[tid + 1];
      double& c = per_cell.empty() ? per_thread[tid] : per_cell[t];
      if (in_range) c += loc.c;
      for (int i = 0; i < n; ++i) {
        const int fi = free[i];
        if (fi >= 0) {
          if (part.owner[fi] != tid) continue;
          double bi = loc.b[i];
          for (int j = 0; j < n; ++j)
            if (free[j] < 0) bi -= loc.K(i, j) * xd[dofs[j]];  // a fixed DOF's coupling
          b[fi] += bi;
        } else if (in_range) {
          const double xi = xd[dofs[i]];
          c -= loc.b[i] * xi;
          for (int j = 0; j < n; ++j)
            if (free[j] < 0) c += 0.5 * loc.K(i, j) * xi * xd[dofs[j]];
        }
      }
      for (int j = 0; j < n; ++j) {
        const int fj = free[j];
        if (fj < 0 || part.owner[fj] != tid) continue;
        for (int i = 0; i < n; ++i)
          if (free[i] >= 0) values[entry_position(a, free[i], fj)] += loc.K(i, j);
      }
    }
  }
  if (out_of_time) throw TimeLimitReached(kStage);
  double constant = 0.0;
  for (double c : per_cell.empty() ? per_thread : per_cell) constant += c;
  return constant;
}

#define FOSLS_SCATTER(Space)                                                            \
  template AssemblyPattern assembly_pattern<Space>(const Space&, int, const Deadline&); \
  template double scatter_local_systems<Space>(                                         \
      const Space&, AssemblyPattern&, const Vector&, Vector&,                           \
      const std::function<void(int, LocalSystem<Space::kCellDofs>&)>&, ConstantSum,     \
      const Deadline&);
FOSLS_SCATTER(FoslsSpace<2>)
FOSLS_SCATTER(FoslsSpace<3>)
FOSLS_SCATTER(P2Rt1Space)
#undef FOSLS_SCATTER

}  // namespace fosls
