#include "fem/transfer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "fem/simplex_element.hpp"

namespace fosls {

double parent_facet_share(const Mesh& fine, const RefinementMaps& maps, int f) {
  // A kept edge is the one whose end points are both coarse vertices (refinement.hpp).
  const auto& pq = fine.edge(f);
  return pq[0] < maps.num_coarse_vertices && pq[1] < maps.num_coarse_vertices ? 1.0 : 0.5;
}

double parent_facet_share(const TetMesh&, const TetRefinementMaps& maps, int f) {
  // Exact from the refinement (¼ under red refinement; ½, ¼, … or 1 under bisection).
  return maps.parent_face_share[f];
}

namespace {

/// Where fine facet f (inside a coarse cell) lies for the coarse RT0 field's flux through it:
/// a point of it and |f| n_f. 2D: on the coarse triangle's geometry, a midpoint at its
/// unsnapped position (cartesian_prolongation); 3D: the fine face as it is.
std::pair<Point, Point> interior_facet(const Mesh& coarse, const Mesh& fine,
                                       const RefinementMaps& maps, int f) {
  const int ncv = coarse.num_vertices();
  auto coarse_position = [&](int v) {
    return v < ncv ? coarse.vertex(v) : coarse.edge_midpoint(maps.midpoint_edge[v - ncv]);
  };
  const auto& pq = fine.edge(f);
  const Point p = coarse_position(pq[0]), q = coarse_position(pq[1]);
  const Point d = q - p;
  return {0.5 * (p + q), Point(d.y(), -d.x())};  // the midpoint, |f| n_f
}

std::pair<Point3, Point3> interior_facet(const TetMesh&, const TetMesh& fine,
                                         const TetRefinementMaps&, int f) {
  return {fine.face_centroid(f), fine.face_area(f) * fine.face_normal(f)};
}

/// The sign of the agreement of fine facet f's global normal with its parent's.
int parent_facet_sign(const Mesh&, const Mesh&, const RefinementMaps& maps, int f) {
  return maps.parent_sign[f];
}

int parent_facet_sign(const TetMesh& coarse, const TetMesh& fine, const TetRefinementMaps& maps,
                      int f) {
  return fine.face_normal(f).dot(coarse.face_normal(maps.parent_face[f])) > 0 ? 1 : -1;
}

}  // namespace

template <int dim>
Eigen::SparseMatrix<double> cartesian_prolongation(const SimplexMesh<dim>& coarse,
                                                   const SimplexMesh<dim>& fine,
                                                   const SimplexRefinementMaps<dim>& maps) {
  const int ncv = coarse.num_vertices(), nfv = fine.num_vertices();
  auto u = [](int v, int c) { return dim * v + c; };
  auto sc = [ncv](int f, int i) { return dim * ncv + dim * f + i; };
  auto sf = [nfv](int f, int i) { return dim * nfv + dim * f + i; };
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(2 * dim * nfv + (dim + 1) * dim * fine.num_facets());
  for (int v = 0; v < nfv; ++v)
    for (int c = 0; c < dim; ++c) {
      if (v < ncv) {
        t.emplace_back(u(v, c), u(v, c), 1.0);
      } else {
        for (int end : maps.midpoint_parents(coarse, v - ncv))
          t.emplace_back(u(v, c), u(end, c), 0.5);
      }
    }
  for (int f = 0; f < fine.num_facets(); ++f) {
    if (const int parent = maps.parent_facet(f); parent >= 0) {
      // The normal component of RT0 is constant on a facet: a part carries its share.
      const double share =
          parent_facet_share(fine, maps, f) * parent_facet_sign(coarse, fine, maps, f);
      for (int i = 0; i < dim; ++i) t.emplace_back(sf(f, i), sc(parent, i), share);
      continue;
    }
    const int tc = maps.parent_cell_of_facet(f);
    const SimplexElement<dim> e(coarse, tc);
    const auto [x, scaled_normal] = interior_facet(coarse, fine, maps, f);
    for (int k = 0; k <= dim; ++k) {
      // ψ_k is linear: its flux through a flat facet is its value at the centroid times |f| n_f.
      const double flux = e.rt0(k, x).dot(scaled_normal);
      for (int i = 0; i < dim; ++i) t.emplace_back(sf(f, i), sc(coarse.cell_facet(tc, k), i), flux);
    }
  }
  Eigen::SparseMatrix<double> p(dim * nfv + dim * fine.num_facets(),
                                dim * ncv + dim * coarse.num_facets());
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

namespace {

/// 2D, curved contact edges: each half's tangential flux is routed, half of it each way, into
/// the other half through the coarse triangle (free_prolongation), so that the fine triangles
/// of both halves are left with the same small residual; as triplets of the free transfer.
void route_tangential_flux(const FoslsSpace<2>& coarse, const FoslsSpace<2>& fine,
                           const RefinementMaps& maps, const Eigen::SparseMatrix<double>& rotated,
                           std::vector<Eigen::Triplet<double>>& t) {
  using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const Mesh& mesh = fine.mesh();
  std::map<int, std::array<int, 2>> halves;
  for (int f = 0; f < mesh.num_edges(); ++f) {
    const int e = maps.parent_edge[f];
    if (e < 0 || !fine.is_contact_edge(f) || coarse.mesh().edge_curve(e) < 0) continue;
    if (fine.free_index(fine.sigma_dof(f, 1)) >= 0) continue;  // frictional: S_t carries it
    auto& h = halves.try_emplace(e, std::array<int, 2>{-1, -1}).first->second;
    h[h[0] < 0 ? 0 : 1] = f;
  }
  if (halves.empty()) return;
  auto add = [&](int row, int col, double value) {
    const int rf = fine.free_index(row), cf = coarse.free_index(col);
    if (rf >= 0 && cf >= 0 && std::abs(value) > kTransferNoise) t.emplace_back(rf, cf, value);
  };
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
}

}  // namespace

template <int dim>
Eigen::SparseMatrix<double> free_prolongation(const FoslsSpace<dim>& coarse,
                                              const FoslsSpace<dim>& fine,
                                              const SimplexRefinementMaps<dim>& maps,
                                              const Eigen::SparseMatrix<double>& cartesian) {
  const Eigen::SparseMatrix<double> rotated =
      Eigen::SparseMatrix<double>(fine.rotation().transpose()) * cartesian * coarse.rotation();
  std::vector<Eigen::Triplet<double>> t = free_triplets(rotated, fine, coarse, kTransferNoise);
  if constexpr (dim == 2) route_tangential_flux(coarse, fine, maps, rotated, t);
  Eigen::SparseMatrix<double> p(fine.num_free(), coarse.num_free());
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

template Eigen::SparseMatrix<double> cartesian_prolongation<2>(const Mesh&, const Mesh&,
                                                               const RefinementMaps&);
template Eigen::SparseMatrix<double> cartesian_prolongation<3>(const TetMesh&, const TetMesh&,
                                                               const TetRefinementMaps&);
template Eigen::SparseMatrix<double> free_prolongation<2>(const FoslsSpace<2>&,
                                                          const FoslsSpace<2>&,
                                                          const RefinementMaps&,
                                                          const Eigen::SparseMatrix<double>&);
template Eigen::SparseMatrix<double> free_prolongation<3>(const FoslsSpace<3>&,
                                                          const FoslsSpace<3>&,
                                                          const TetRefinementMaps&,
                                                          const Eigen::SparseMatrix<double>&);

}  // namespace fosls
