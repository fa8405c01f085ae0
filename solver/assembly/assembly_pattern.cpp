#include "assembly/assembly_pattern.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <string>

namespace fosls {

std::array<int, 12> triangle_dofs(const FoslsSpace<2>& space, int t) {
  const Mesh& mesh = space.mesh();
  std::array<int, 12> d;
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 2; ++c) {
      d[2 * k + c] = space.u_dof(mesh.triangle(t)[k], c);
      d[6 + 2 * k + c] = space.sigma_dof(mesh.triangle_edge(t, k), c);
    }
  return d;
}

namespace {

/// Free DOF → triangles holding it (CSR, triangles increasing).
struct DofTriangles {
  std::vector<int> offset, triangles;
};

DofTriangles dof_triangles(const FoslsSpace<2>& space) {
  const int n = space.num_free(), nt = space.mesh().num_triangles();
  DofTriangles out;
  out.offset.assign(n + 1, 0);
  for (int t = 0; t < nt; ++t)
    for (int d : triangle_dofs(space, t))
      if (const int f = space.free_index(d); f >= 0) ++out.offset[f + 1];
  for (int f = 0; f < n; ++f) out.offset[f + 1] += out.offset[f];
  out.triangles.resize(out.offset[n]);
  std::vector<int> next(out.offset.begin(), out.offset.end() - 1);
  for (int t = 0; t < nt; ++t)
    for (int d : triangle_dofs(space, t))
      if (const int f = space.free_index(d); f >= 0) out.triangles[next[f]++] = t;
  return out;
}

}  // namespace

AssemblyPattern assembly_pattern(const FoslsSpace<2>& space, int threads,
                                 const Deadline& deadline) {
  const int n = space.num_free(), nt = space.mesh().num_triangles();
  // Each pass over the mesh takes as long as a part of the element loop: checked between them,
  // and in the column passes every so many columns (an OpenMP loop cannot be left: the columns
  // after the deadline are skipped, and the check after the pass throws).
  const std::string stage = "assembling the finest level";
  std::atomic<bool> late{false};
  auto out_of_time = [&](int f) {
    if (deadline.is_set() && f % Deadline::kPollEvery == 0 && deadline.passed())
      late.store(true, std::memory_order_relaxed);
    return late.load(std::memory_order_relaxed);
  };
  const DofTriangles dt = dof_triangles(space);
  deadline.check(stage);
  AssemblyPattern out;

  // Column f holds the free DOFs of the triangles around f: counted first, then filled.
  std::vector<int> outer(n + 1, 0);
  auto column = [&](int f, std::vector<int>& mark, std::vector<int>& rows) {
    rows.clear();
    for (int k = dt.offset[f]; k < dt.offset[f + 1]; ++k)
      for (int d : triangle_dofs(space, dt.triangles[k]))
        if (const int g = space.free_index(d); g >= 0 && mark[g] != f)
          mark[g] = f, rows.push_back(g);
  };
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
  deadline.check(stage);
  SparseMatrix& a = out.matrix;
  a.resize(n, n);
  a.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), a.outerIndexPtr());
  std::fill(a.valuePtr(), a.valuePtr() + outer[n], 0.0);
  deadline.check(stage);
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

  deadline.check(stage);
  AssemblyPartition& p = out.partition;
  threads = std::max(1, threads);
  p.range_begin.resize(threads + 1);
  for (int t = 0; t <= threads; ++t)
    p.range_begin[t] = static_cast<int>(static_cast<long long>(nt) * t / threads);
  auto range_of = [&p, threads](int triangle) {
    return static_cast<int>(
               std::upper_bound(p.range_begin.begin(), p.range_begin.end() - 1, triangle) -
               p.range_begin.begin()) -
           1;
  };
  p.owner.resize(n);
  for (int f = 0; f < n; ++f) p.owner[f] = range_of(dt.triangles[dt.offset[f]]);
  p.triangles.assign(threads, {});
  std::vector<char> visits(threads);
  for (int t = 0; t < nt; ++t) {
    std::fill(visits.begin(), visits.end(), 0);
    visits[range_of(t)] = 1;
    for (int d : triangle_dofs(space, t))
      if (const int f = space.free_index(d); f >= 0) visits[p.owner[f]] = 1;
    for (int k = 0; k < threads; ++k)
      if (visits[k]) p.triangles[k].push_back(t);
  }
  return out;
}

}  // namespace fosls
