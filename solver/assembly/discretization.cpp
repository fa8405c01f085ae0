#include "assembly/discretization.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/patch_blocks.hpp"
#include "fem/transfer.hpp"

namespace fosls {

Discretization::Discretization(MeshHierarchy meshes, ProblemData<2> data, const Deadline& deadline)
    : meshes_(std::move(meshes)), data_(std::move(data)) {
  const auto roles = data_.boundary_roles();
  for (const Mesh& m : meshes_.meshes) {
    deadline.check("building the finite element spaces");
    spaces_.push_back(std::make_unique<FoslsSpace<2>>(m, roles, obstacle_vertex_normals(m, data_)));
  }
  assembler_ = std::make_unique<FoslsAssembler<2>>(*spaces_.back(), data_);
  // Eigen 3.4's SparseMatrix has no move assignment: the matrix is swapped in, not copied.
  AssembledProblem assembled = assembler_->assemble_system(deadline);
  SparseMatrix a;
  a.swap(assembled.qp.A);
  problem_ = std::move(assembled);
  problem_.qp.A.swap(a);
}

std::vector<std::vector<int>> vertex_patches(const FoslsSpace<2>& space, std::array<int, 2>* split,
                                             const std::vector<char>& selected) {
  const Mesh& mesh = space.mesh();
  const auto vertex_edges = mesh.vertex_edges();
  const VertexBlocks blocks = two_vertex_blocks(mesh);
  std::vector<std::vector<int>> patches;
  patches.reserve(mesh.num_vertices());
  for (int k = 0; k < mesh.num_vertices(); ++k) {
    for (int b = 0; b < 2; ++b)
      if (split && k == blocks.ends[b]) (*split)[b] = static_cast<int>(patches.size());
    const int v = blocks.order[k];
    if (!selected.empty() && !selected[v]) continue;
    std::vector<int> p;
    for (int c = 0; c < 2; ++c)
      if (int f = space.free_index(space.u_dof(v, c)); f >= 0) p.push_back(f);
    for (int e : vertex_edges[v])
      for (int i = 0; i < 2; ++i)
        if (int f = space.free_index(space.sigma_dof(e, i)); f >= 0) p.push_back(f);
    if (!p.empty()) patches.push_back(std::move(p));
  }
  for (int b = 0; b < 2; ++b)
    if (split && blocks.ends[b] == mesh.num_vertices())
      (*split)[b] = static_cast<int>(patches.size());
  return patches;
}

std::vector<char> new_vertices_and_neighbours(const Mesh& fine, const RefinementMaps& maps) {
  std::vector<char> selected(fine.num_vertices(), 0);
  for (int e = 0; e < fine.num_edges(); ++e) {
    const auto& ab = fine.edge(e);
    if (ab[0] >= maps.num_coarse_vertices || ab[1] >= maps.num_coarse_vertices)
      selected[ab[0]] = selected[ab[1]] = 1;
  }
  return selected;
}

std::vector<int> contact_strip(const FoslsSpace<2>& space, int layers) {
  const Mesh& mesh = space.mesh();
  std::vector<char> on_contact(mesh.num_vertices(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (space.is_contact_edge(e))
      for (int v : mesh.edge(e)) on_contact[v] = 1;
  for (int layer = 1; layer < layers; ++layer) {
    std::vector<char> next = on_contact;
    for (int t = 0; t < mesh.num_triangles(); ++t) {
      const auto& tri = mesh.triangle(t);
      if (on_contact[tri[0]] || on_contact[tri[1]] || on_contact[tri[2]])
        for (int v : tri) next[v] = 1;
    }
    on_contact = next;
  }
  std::vector<char> taken(space.num_free(), 0);
  std::vector<int> strip;
  auto take = [&](int full) {
    const int f = space.free_index(full);
    if (f >= 0 && !taken[f]) taken[f] = 1, strip.push_back(f);
  };
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto& tri = mesh.triangle(t);
    if (!on_contact[tri[0]] && !on_contact[tri[1]] && !on_contact[tri[2]]) continue;
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 2; ++c) {
        take(space.u_dof(tri[k], c));
        take(space.sigma_dof(mesh.triangle_edge(t, k), c));
      }
  }
  std::sort(strip.begin(), strip.end());
  return strip;
}

namespace {

/// The fine RT0 field that moves one unit of normal flux from boundary edge `from` to boundary
/// edge `to` (the two halves of one coarse contact edge) with zero divergence in every fine
/// triangle: the vector flux S·n_from leaves `from`'s triangle through its edge into the
/// interior of the coarse triangle, crosses the fine triangles between the halves and comes
/// out through `to`. Returned as free DOFs of the fine space with their coefficients; the
/// first entry is `to`'s S_n, n_from·n_to (1 on a straight edge; the tangential part, which
/// S_t = 0 does not allow, is dropped on curved edges).
std::vector<std::pair<int, double>> flux_move(const FoslsSpace<2>& space,
                                              const RefinementMaps& maps, int from, int to) {
  const Mesh& mesh = space.mesh();
  const Point n = mesh.edge_normal(from);
  const auto path = flux_path(mesh, maps, from, to);
  if (path.empty()) return {};
  std::vector<std::pair<int, double>> moves;
  moves.emplace_back(space.free_index(space.sigma_dof(to, 0)), n.dot(mesh.edge_normal(to)));
  for (const auto& [f, sign] : path)
    for (int i = 0; i < 2; ++i)
      if (const int dof = space.free_index(space.sigma_dof(f, i)); dof >= 0 && n[i] != 0.0)
        moves.emplace_back(dof, sign * n[i]);
  return moves;
}

}  // namespace

int Discretization::coarsest_solver_level(double max_turn) const {
  for (int j = 0; j + 1 < num_levels(); ++j) {
    const FoslsSpace<2>& space = *spaces_[j];
    const Mesh& mesh = space.mesh();
    double turn = 0.0;
    for (int e = 0; e < mesh.num_edges(); ++e) {
      const int c = mesh.edge_curve(e);
      if (c < 0 || !space.is_contact_edge(e)) continue;
      const double ratio = 0.5 * mesh.edge_length(e) / mesh.curves()[c].radius;
      turn = std::max(turn, 2.0 * std::asin(std::min(1.0, ratio)));
    }
    if (turn <= max_turn) return j;
  }
  return num_levels() - 1;
}

LevelHierarchy Discretization::build_level_hierarchy() const {
  LevelHierarchy h;
  const int coarsest = coarsest_solver_level();
  h.levels.resize(num_levels() - coarsest);
  for (int j = coarsest; j < num_levels(); ++j) {
    const FoslsSpace<2>& fine = *spaces_[j];
    Level& level = h.levels[j - coarsest];
    level.num_dofs = fine.num_free();
    // Local smoothing (Chen, Nochetto and Xu's multilevel methods on graded bisection grids):
    // an intermediate level smooths where it differs from the level below, so that one cycle
    // costs O(N) of the finest level however many bisection levels there are. A uniform
    // level is smoothed everywhere, the finest level always.
    const bool everywhere = j == coarsest || j + 1 == num_levels();
    level.patches =
        vertex_patches(fine, &level.patch_split,
                       everywhere ? std::vector<char>{}
                                  : new_vertices_and_neighbours(fine.mesh(), meshes_.maps[j]));
    level.contact_strip = contact_strip(fine);
    if (j == coarsest) continue;
    const FoslsSpace<2>& coarse = *spaces_[j - 1];
    const RefinementMaps& maps = meshes_.maps[j];
    level.prolongation = free_prolongation(
        coarse, fine, maps, cartesian_prolongation(coarse.mesh(), fine.mesh(), maps));
    // Contact links: every coarse contact edge with its fine children (its two halves and
    // their midpoint, or the edge itself where it was kept).
    const Mesh& cm = coarse.mesh();
    const Mesh& fm = fine.mesh();
    const int ncv = cm.num_vertices();
    std::vector<int> midpoint(cm.num_edges(), -1);
    for (std::size_t k = 0; k < maps.midpoint_edge.size(); ++k)
      midpoint[maps.midpoint_edge[k]] = ncv + static_cast<int>(k);
    std::vector<std::array<int, 2>> children(cm.num_edges(), {-1, -1});
    for (int f = 0; f < fm.num_edges(); ++f) {
      int e = maps.parent_edge[f];
      if (e < 0 || !coarse.is_contact_edge(e)) continue;
      // The half that touches the coarse edge's first end point comes first.
      bool first = fm.edge(f)[0] == cm.edge(e)[0] || fm.edge(f)[1] == cm.edge(e)[0];
      children[e][first ? 0 : 1] = f;
    }
    auto normal_u = [](const FoslsSpace<2>& s, int v) {
      return s.is_contact_vertex(v) ? s.free_index(s.u_dof(v, 0)) : -1;
    };
    for (int e = 0; e < cm.num_edges(); ++e) {
      if (!coarse.is_contact_edge(e)) continue;
      ContactLink link;
      const auto& ab = cm.edge(e);
      link.coarse_un_a = normal_u(coarse, ab[0]);
      link.coarse_un_b = normal_u(coarse, ab[1]);
      link.fine_un_a = normal_u(fine, ab[0]);
      link.fine_un_b = normal_u(fine, ab[1]);
      link.fine_un_mid = midpoint[e] >= 0 ? normal_u(fine, midpoint[e]) : -1;
      link.coarse_sn = coarse.free_index(coarse.sigma_dof(e, 0));
      for (int k = 0; k < 2; ++k) {
        if (children[e][k] < 0) continue;  // a kept edge has one child
        link.fine_sn[k] = fine.free_index(fine.sigma_dof(children[e][k], 0));
        link.sn_weight[k] = level.prolongation.coeff(link.fine_sn[k], link.coarse_sn);
      }
      if (link.fine_sn[0] >= 0 && link.fine_sn[1] >= 0)
        for (int k = 0; k < 2; ++k)
          link.flux_moves[k] = flux_move(fine, maps, children[e][k], children[e][1 - k]);
      level.links.push_back(link);
    }
  }
  return h;
}

}  // namespace fosls
