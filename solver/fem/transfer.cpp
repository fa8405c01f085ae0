#include "fem/transfer.hpp"

#include "fem/element_geometry.hpp"

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
    ElementGeometry geo(coarse, tc);
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

Eigen::SparseMatrix<double> free_prolongation(const FoslsSpace& coarse, const FoslsSpace& fine,
                                              const Eigen::SparseMatrix<double>& cartesian) {
  Eigen::SparseMatrix<double> rotated =
      Eigen::SparseMatrix<double>(fine.rotation().transpose()) * cartesian * coarse.rotation();
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(rotated.nonZeros());
  for (int col = 0; col < rotated.outerSize(); ++col) {
    int cf = coarse.free_index(col);
    if (cf < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(rotated, col); it; ++it) {
      int rf = fine.free_index(static_cast<int>(it.row()));
      if (rf >= 0 && std::abs(it.value()) > 1e-15) t.emplace_back(rf, cf, it.value());
    }
  }
  Eigen::SparseMatrix<double> p(fine.num_free(), coarse.num_free());
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

}  // namespace fosls
