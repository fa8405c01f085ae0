#include "fem/transfer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "fem/simplex_element.hpp"

namespace fosls {

Eigen::SparseMatrix<double> cartesian_prolongation(const Mesh& coarse, const Mesh& fine,
                                                   const RefinementMaps& maps) {
  const int ncv = coarse.num_vertices(), nce = coarse.num_edges();
  const int nfv = fine.num_vertices(), nfe = fine.num_edges();
  auto u = [](int v, int c) { return 2 * v + c; };
  auto sc = [ncv](int e, int i) { return 2 * ncv + 2 * e + i; };
  auto sf = [nfv](int e, int i) { return 2 * nfv + 2 * e + i; };
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(4 * nfv + 6 * nfe);
  for (int v = 0; v < nfv; ++v)
    for (int c = 0; c < 2; ++c) {
      if (v < ncv) {
        t.emplace_back(u(v, c), u(v, c), 1.0);
      } else {
        const auto& pq = coarse.edge(maps.midpoint_edge[v - ncv]);
        t.emplace_back(u(v, c), u(pq[0], c), 0.5);
        t.emplace_back(u(v, c), u(pq[1], c), 0.5);
      }
    }
  // Where a fine vertex lies on the coarse mesh: a midpoint at its unsnapped position.
  auto coarse_position = [&](int v) {
    return v < ncv ? coarse.vertex(v) : coarse.edge_midpoint(maps.midpoint_edge[v - ncv]);
  };
  for (int f = 0; f < nfe; ++f) {
    const auto& pq = fine.edge(f);
    if (maps.parent_edge[f] >= 0) {
      // The normal component of RT0 is constant along an edge: a half carries half the flux,
      // a kept edge all of it.
      const double share = (pq[0] < ncv && pq[1] < ncv) ? 1.0 : 0.5;
      for (int i = 0; i < 2; ++i)
        t.emplace_back(sf(f, i), sc(maps.parent_edge[f], i), share * maps.parent_sign[f]);
      continue;
    }
    const int tc = maps.parent_triangle[f];
    const SimplexElement<2> geo(coarse, tc);
    Point p = coarse_position(pq[0]), q = coarse_position(pq[1]);
    Point d = q - p;
    Point scaled_normal(d.y(), -d.x());  // |f| n_f
    Point mid = 0.5 * (p + q);
    for (int k = 0; k < 3; ++k) {
      double flux = geo.rt0(k, mid).dot(scaled_normal);
      for (int i = 0; i < 2; ++i)
        t.emplace_back(sf(f, i), sc(coarse.triangle_edge(tc, k), i), flux);
    }
  }
  Eigen::SparseMatrix<double> p(2 * nfv + 2 * nfe, 2 * ncv + 2 * nce);
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

std::vector<std::pair<int, int>> flux_path(const Mesh& fine, const RefinementMaps& maps, int from,
                                           int to) {
  // Breadth-first search across fine edges interior to the coarse triangle (no parent edge).
  const int start = fine.edge_triangles(from)[0], goal = fine.edge_triangles(to)[0];
  std::map<int, std::pair<int, int>> came_from;  // triangle → (previous triangle, edge)
  came_from[start] = {-1, -1};
  std::vector<int> queue = {start};
  for (std::size_t q = 0; q < queue.size() && !came_from.count(goal); ++q) {
    const int t = queue[q];
    for (int k = 0; k < 3; ++k) {
      const int f = fine.triangle_edge(t, k);
      if (maps.parent_edge[f] >= 0) continue;
      const auto& tt = fine.edge_triangles(f);
      const int next = tt[0] == t ? tt[1] : tt[0];
      if (next < 0 || came_from.count(next)) continue;
      came_from[next] = {t, f};
      queue.push_back(next);
    }
  }
  std::vector<std::pair<int, int>> path;
  if (!came_from.count(goal)) return path;
  for (int t = goal; came_from[t].first >= 0; t = came_from[t].first) {
    const auto [previous, f] = came_from[t];
    for (int k = 0; k < 3; ++k)
      if (fine.triangle_edge(previous, k) == f)
        path.emplace_back(f, fine.triangle_edge_sign(previous, k));
  }
  std::reverse(path.begin(), path.end());
  return path;
}

Eigen::SparseMatrix<double> free_prolongation(const FoslsSpace<2>& coarse,
                                              const FoslsSpace<2>& fine, const RefinementMaps& maps,
                                              const Eigen::SparseMatrix<double>& cartesian) {
  using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const Eigen::SparseMatrix<double> rotated =
      Eigen::SparseMatrix<double>(fine.rotation().transpose()) * cartesian * coarse.rotation();
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(rotated.nonZeros());
  auto add = [&](int row, int col, double value) {
    const int rf = fine.free_index(row), cf = coarse.free_index(col);
    if (rf >= 0 && cf >= 0 && std::abs(value) > 1e-15) t.emplace_back(rf, cf, value);
  };
  for (int col = 0; col < rotated.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(rotated, col); it; ++it)
      add(static_cast<int>(it.row()), col, it.value());
  // Tangential flux on the halves of curved contact edges: route half 0's into half 1 and
  // half 1's into half 0, half of each, so that the fine triangles of both halves are left
  // with the same small residual.
  const Mesh& mesh = fine.mesh();
  std::map<int, std::array<int, 2>> halves;
  for (int f = 0; f < mesh.num_edges(); ++f) {
    const int e = maps.parent_edge[f];
    if (e < 0 || !fine.is_contact_edge(f) || coarse.mesh().edge_curve(e) < 0) continue;
    if (fine.free_index(fine.sigma_dof(f, 1)) >= 0) continue;  // frictional: S_t carries it
    auto& h = halves.try_emplace(e, std::array<int, 2>{-1, -1}).first->second;
    h[h[0] < 0 ? 0 : 1] = f;
  }
  if (halves.empty())
    return [&] {
      Eigen::SparseMatrix<double> p(fine.num_free(), coarse.num_free());
      p.setFromTriplets(t.begin(), t.end());
      return p;
    }();
  const RowMajor rows = rotated;
  for (const auto& [e, h] : halves) {
    if (h[1] < 0) continue;
    const auto path = flux_path(mesh, maps, h[0], h[1]);
    if (path.empty()) continue;
    std::map<int, Point> routed;  // coarse column → vector flux carried from half 0 to half 1
    for (int k = 0; k < 2; ++k) {
      const Point n = mesh.edge_normal(h[k]);
      const Point tangent(-n.y(), n.x());
      const double direction = k == 0 ? 0.5 : -0.5;
      for (RowMajor::InnerIterator it(rows, fine.sigma_dof(h[k], 1)); it; ++it)
        routed.try_emplace(static_cast<int>(it.col()), Point::Zero()).first->second +=
            direction * it.value() * tangent;
    }
    for (const auto& [col, g] : routed)
      for (const auto& [f, sign] : path)
        for (int i = 0; i < 2; ++i) add(fine.sigma_dof(f, i), col, sign * g[i]);
  }
  Eigen::SparseMatrix<double> p(fine.num_free(), coarse.num_free());
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

}  // namespace fosls
