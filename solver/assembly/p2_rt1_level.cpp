#include "assembly/p2_rt1_level.hpp"

#include <algorithm>

#include "assembly/patch_blocks.hpp"
#include "fem/simplex_element.hpp"

namespace fosls {

Eigen::SparseMatrix<double> order2_embedding(const FoslsSpace<2>& lowest,
                                             const P2Rt1Space& order2) {
  const Mesh& mesh = lowest.mesh();
  std::vector<Eigen::Triplet<double>> t;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int c = 0; c < 2; ++c) t.emplace_back(order2.u_dof(v, c), lowest.u_dof(v, c), 1.0);
  for (int e = 0; e < mesh.num_edges(); ++e)
    for (int c = 0; c < 2; ++c) {
      for (int v : mesh.edge(e))
        t.emplace_back(order2.u_dof(order2.midpoint_node(e), c), lowest.u_dof(v, c), 0.5);
      for (int j = 0; j < 2; ++j)
        t.emplace_back(order2.sigma_edge_dof(e, j, c), lowest.sigma_dof(e, c), 0.5);
    }
  for (int tr = 0; tr < mesh.num_triangles(); ++tr) {
    const SimplexElement<2> g(mesh, tr);
    const Point centroid = (g.a[0] + g.a[1] + g.a[2]) / 3.0;
    for (int k = 0; k < 3; ++k) {
      const Point mean = g.rt0(k, centroid);  // RT0 is linear: its mean is its centroid value
      for (int m = 0; m < 2; ++m)
        for (int i = 0; i < 2; ++i)
          t.emplace_back(order2.sigma_mean_dof(tr, m, i),
                         lowest.sigma_dof(mesh.triangle_edge(tr, k), i), mean[m]);
    }
  }
  Eigen::SparseMatrix<double> p(order2.num_dofs(), lowest.num_dofs());
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

Vector lowest_order_interpolant(const FoslsSpace<2>& lowest, const P2Rt1Space& order2,
                                const Vector& x_full) {
  const Mesh& mesh = lowest.mesh();
  const Vector cartesian = order2.rotation() * x_full;
  Vector x = Vector::Zero(lowest.num_dofs());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int c = 0; c < 2; ++c) x[lowest.u_dof(v, c)] = cartesian[order2.u_dof(v, c)];
  for (int e = 0; e < mesh.num_edges(); ++e)
    for (int i = 0; i < 2; ++i)
      x[lowest.sigma_dof(e, i)] =
          cartesian[order2.sigma_edge_dof(e, 0, i)] + cartesian[order2.sigma_edge_dof(e, 1, i)];
  return lowest.rotation().transpose() * x;
}

namespace {

/// The embedding between the free DOFs of both spaces in their rotated coordinates.
SparseMatrix free_embedding(const FoslsSpace<2>& lowest, const P2Rt1Space& order2) {
  const Eigen::SparseMatrix<double> rotated =
      order2.rotation().transpose() * order2_embedding(lowest, order2) * lowest.rotation();
  std::vector<Eigen::Triplet<double>> t;
  for (int col = 0; col < rotated.outerSize(); ++col) {
    const int fc = lowest.free_index(col);
    if (fc < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(rotated, col); it; ++it) {
      const int fr = order2.free_index(static_cast<int>(it.row()));
      if (fr >= 0 && it.value() != 0.0) t.emplace_back(fr, fc, it.value());
    }
  }
  SparseMatrix p(order2.num_free(), lowest.num_free());
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

/// Free DOFs of the vertex patches in two_vertex_blocks' order (the same stars as the lowest
/// order's patches, so its two blocks are independent here too).
std::vector<std::vector<int>> order2_patches(const P2Rt1Space& space, std::array<int, 2>& split) {
  const Mesh& mesh = space.mesh();
  const auto vertex_edges = mesh.vertex_edges();
  std::vector<std::vector<int>> vertex_triangles(mesh.num_vertices());
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int v : mesh.triangle(t)) vertex_triangles[v].push_back(t);
  const VertexBlocks blocks = two_vertex_blocks(mesh);
  std::vector<std::vector<int>> patches;
  split = {0, 0};
  for (int k = 0; k < mesh.num_vertices(); ++k) {
    for (int b = 0; b < 2; ++b)
      if (k == blocks.ends[b]) split[b] = static_cast<int>(patches.size());
    const int v = blocks.order[k];
    std::vector<int> p;
    auto take = [&](int dof) {
      if (const int f = space.free_index(dof); f >= 0) p.push_back(f);
    };
    for (int c = 0; c < 2; ++c) take(space.u_dof(v, c));
    for (int e : vertex_edges[v])
      for (int c = 0; c < 2; ++c) {
        take(space.u_dof(space.midpoint_node(e), c));
        for (int j = 0; j < 2; ++j) take(space.sigma_edge_dof(e, j, c));
      }
    for (int t : vertex_triangles[v])
      for (int m = 0; m < 2; ++m)
        for (int i = 0; i < 2; ++i) take(space.sigma_mean_dof(t, m, i));
    if (!p.empty()) patches.push_back(std::move(p));
  }
  for (int b = 0; b < 2; ++b)
    if (blocks.ends[b] == mesh.num_vertices()) split[b] = static_cast<int>(patches.size());
  return patches;
}

/// Free DOFs of the triangles within two layers of the contact boundary, sorted.
std::vector<int> order2_contact_strip(const P2Rt1Space& space) {
  const Mesh& mesh = space.mesh();
  std::vector<char> near(mesh.num_vertices(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (space.is_contact_edge(e))
      for (int v : mesh.edge(e)) near[v] = 1;
  auto touches = [&](int t) {
    const auto& tri = mesh.triangle(t);
    return near[tri[0]] || near[tri[1]] || near[tri[2]];
  };
  std::vector<char> second = near;
  for (int t = 0; t < mesh.num_triangles(); ++t)
    if (touches(t))
      for (int v : mesh.triangle(t)) second[v] = 1;
  near = second;
  std::vector<int> strip;
  for (int t = 0; t < mesh.num_triangles(); ++t)
    if (touches(t))
      for (int dof : space.cell_dofs(t))
        if (const int f = space.free_index(dof); f >= 0) strip.push_back(f);
  std::sort(strip.begin(), strip.end());
  strip.erase(std::unique(strip.begin(), strip.end()), strip.end());
  return strip;
}

/// Contact edge e's link: its lowest-order U_n and S_n with the order-2 ones. Moving S_n from
/// one end to the other keeps the edge's flux; the triangle's σ means are the path on which
/// the truncated hierarchy makes the move divergence free.
ContactLink order2_link(const FoslsSpace<2>& lowest, const P2Rt1Space& order2,
                        const SparseMatrix& p, int e) {
  const Mesh& mesh = lowest.mesh();
  ContactLink link;
  auto lowest_un = [&](int v) {
    return lowest.is_contact_vertex(v) ? lowest.free_index(lowest.u_dof(v, 0)) : -1;
  };
  auto order2_un = [&](int a) {
    return order2.is_contact_node(a) ? order2.free_index(order2.u_dof(a, 0)) : -1;
  };
  const auto& ab = mesh.edge(e);
  link.coarse_un_a = lowest_un(ab[0]);
  link.coarse_un_b = lowest_un(ab[1]);
  link.fine_un_a = order2_un(ab[0]);
  link.fine_un_b = order2_un(ab[1]);
  link.fine_un_mid = order2_un(order2.midpoint_node(e));
  link.coarse_sn = lowest.free_index(lowest.sigma_dof(e, 0));
  for (int j = 0; j < 2; ++j) {
    link.fine_sn[j] = order2.free_index(order2.sigma_edge_dof(e, j, 0));
    link.sn_weight[j] = p.coeff(link.fine_sn[j], link.coarse_sn);
  }
  const int t = mesh.edge_triangles(e)[0];
  for (int k = 0; k < 2; ++k) {
    link.flux_moves[k].emplace_back(link.fine_sn[1 - k], 1.0);
    for (int m = 0; m < 2; ++m)
      for (int i = 0; i < 2; ++i)
        link.flux_moves[k].emplace_back(order2.free_index(order2.sigma_mean_dof(t, m, i)), 0.0);
  }
  return link;
}

}  // namespace

Level order2_level(const FoslsSpace<2>& lowest, const P2Rt1Space& order2) {
  Level level;
  level.num_dofs = order2.num_free();
  level.prolongation = free_embedding(lowest, order2);
  level.patches = order2_patches(order2, level.patch_split);
  level.contact_strip = order2_contact_strip(order2);
  for (int e = 0; e < lowest.mesh().num_edges(); ++e)
    if (lowest.is_contact_edge(e))
      level.links.push_back(order2_link(lowest, order2, level.prolongation, e));
  return level;
}

}  // namespace fosls
