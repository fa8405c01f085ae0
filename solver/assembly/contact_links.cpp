#include "assembly/contact_links.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "fem/transfer.hpp"
#include "mesh/composed_refinement.hpp"

namespace fosls {

namespace {

using Move = std::vector<std::pair<int, double>>;

/// The free U_n of a contact vertex, −1 elsewhere.
template <int dim>
int normal_u(const FoslsSpace<dim>& s, int v) {
  return s.is_contact_vertex(v) ? s.free_index(s.u_dof(v, 0)) : -1;
}

/// The edges of coarse facet F as vertex pairs: in 2D the facet itself in its orientation, in
/// 3D its three edges.
std::vector<std::array<int, 2>> facet_edges(const Mesh& mesh, int f) { return {mesh.edge(f)}; }

std::vector<std::array<int, 2>> facet_edges(const TetMesh& mesh, int f) {
  const auto& v = mesh.face(f);
  std::vector<std::array<int, 2>> edges;
  for (int k = 0; k < 3; ++k) {
    const auto [a, b] = std::minmax(v[k], v[(k + 1) % 3]);
    edges.push_back({a, b});
  }
  return edges;
}

/// The fine facets inside each coarse contact facet, in their pairs' order: in 2D along the
/// coarse edge from its first end (a kept edge alone), in 3D in fine order.
template <int dim>
std::vector<std::vector<int>> contact_children(const FoslsSpace<dim>& coarse,
                                               const SimplexMesh<dim>& fine,
                                               const SimplexRefinementMaps<dim>& maps) {
  std::vector<std::vector<int>> children(coarse.mesh().num_facets());
  for (int f = 0; f < fine.num_facets(); ++f)
    if (const int parent = maps.parent_facet(f); parent >= 0 && coarse.is_contact_facet(parent))
      children[parent].push_back(f);
  if constexpr (dim == 2)
    for (int e = 0; e < coarse.mesh().num_edges(); ++e) {
      const Point start = coarse.mesh().vertex(coarse.mesh().edge(e)[0]);
      const auto distance = [&](int f) { return (fine.edge_midpoint(f) - start).squaredNorm(); };
      std::sort(children[e].begin(), children[e].end(),
                [&](int f, int g) { return distance(f) < distance(g); });
    }
  return children;
}

/// 2D, a coarse edge's two halves: the fine RT0 field that moves one unit of normal flux from
/// boundary edge `from` to boundary edge `to` with zero divergence in every fine triangle: the
/// vector flux S·n_from leaves `from`'s triangle through its edge into the interior of the coarse
/// triangle, crosses the fine triangles between the halves and comes out through `to`. Its first
/// entry is `to`'s S_n, n_from·n_to (1 on a straight edge; the tangential part, which S_t = 0
/// does not allow, is dropped on curved edges).
Move flux_move_along_path(const FoslsSpace<2>& space, const RefinementMaps& maps, int from,
                          int to) {
  const Mesh& mesh = space.mesh();
  const Point n = mesh.edge_normal(from);
  const auto path = flux_path(mesh, maps, from, to);
  if (path.empty()) return {};
  Move moves;
  moves.emplace_back(space.free_index(space.sigma_dof(to, 0)), n.dot(mesh.edge_normal(to)));
  for (const auto& [f, sign] : path)
    for (int i = 0; i < 2; ++i)
      if (const int dof = space.free_index(space.sigma_dof(f, i)); dof >= 0 && n[i] != 0.0)
        moves.emplace_back(dof, sign * n[i]);
  return moves;
}

/// One unit of normal flux taken off child `from` arrives on child `to` as n_from · n_to of its
/// S_n (the tangential rest falls on the fixed S_t), carried through `interior`, the free σ DOFs
/// of the fine facets inside the coarse cell, whose values the truncation sets with the least
/// energy (solvers/truncated_hierarchy.cpp). 2D's two halves of an edge (interior null) take the
/// path of fine edges between them instead.
template <int dim>
Move flux_move(const FoslsSpace<dim>& fine, const SimplexRefinementMaps<dim>& maps, int from,
               int to, const std::vector<int>* interior) {
  if constexpr (dim == 2)
    if (!interior) return flux_move_along_path(fine, maps, from, to);
  const SimplexMesh<dim>& m = fine.mesh();
  Move move;
  move.emplace_back(fine.free_index(fine.sigma_dof(to, 0)),
                    m.facet_normal(from).dot(m.facet_normal(to)));
  for (int dof : *interior) move.emplace_back(dof, 0.0);
  return move;
}

/// The free σ DOFs of the fine facets inside each coarse cell under a contact facet: the way
/// the flux moves go in 3D, and in 2D across more than two children of an edge.
template <int dim>
std::vector<std::vector<int>> interior_sigma_dofs(const FoslsSpace<dim>& coarse,
                                                  const FoslsSpace<dim>& fine,
                                                  const SimplexRefinementMaps<dim>& maps) {
  const SimplexMesh<dim>& cm = coarse.mesh();
  std::vector<char> under_contact(cm.num_cells(), 0);
  for (int f = 0; f < cm.num_facets(); ++f)
    if (coarse.is_contact_facet(f)) under_contact[cm.facet_cells(f)[0]] = 1;
  std::vector<std::vector<int>> dofs(cm.num_cells());
  for (int f = 0; f < fine.mesh().num_facets(); ++f)
    if (const int t = maps.parent_cell_of_facet(f); t >= 0 && under_contact[t])
      for (int i = 0; i < dim; ++i)
        if (const int dof = fine.free_index(fine.sigma_dof(f, i)); dof >= 0) dofs[t].push_back(dof);
  return dofs;
}

/// Makes the links [first, first + count) of one coarse facet each other's partners (in order),
/// with the factors n_k · n_i between their children `children[2·link + k]`. A link of one child
/// gets its flux move towards its first partner's first child.
template <int dim>
void make_partners(const FoslsSpace<dim>& fine, const SimplexRefinementMaps<dim>& maps,
                   const std::vector<int>& children, const std::vector<int>& interior,
                   std::size_t first, std::size_t count, std::vector<ContactLink>& links) {
  const SimplexMesh<dim>& m = fine.mesh();
  const auto child = [&](std::size_t link, int k) {
    const std::size_t c = 2 * link + static_cast<std::size_t>(k);
    return c < children.size() ? children[c] : -1;
  };
  for (std::size_t a = 0; a < count; ++a) {
    ContactLink& link = links[first + a];
    for (std::size_t b = 0; b < count; ++b) {
      if (b == a) continue;
      LinkPartner& partner = link.partners.emplace_back();
      partner.link = static_cast<int>(first + b);
      for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 2; ++i)
          if (child(a, k) >= 0 && child(b, i) >= 0)
            partner.factor[k][i] = m.facet_normal(child(a, k)).dot(m.facet_normal(child(b, i)));
    }
    if (child(a, 1) < 0 && link.fine_sn[0] >= 0)
      link.flux_moves[0] = flux_move(fine, maps, child(a, 0), child(a == 0 ? 1 : 0, 0), &interior);
  }
}

/// Fine midpoint of each coarse edge whose ends both lie on the contact boundary.
template <int dim>
std::map<std::pair<int, int>, int> contact_midpoints(const FoslsSpace<dim>& coarse,
                                                     const SimplexRefinementMaps<dim>& maps) {
  const SimplexMesh<dim>& cm = coarse.mesh();
  std::vector<char> on_contact(cm.num_vertices(), 0);
  for (int f = 0; f < cm.num_facets(); ++f)
    if (coarse.is_contact_facet(f))
      for (int v : cm.facet(f)) on_contact[v] = 1;
  std::map<std::pair<int, int>, int> midpoint;
  for (int k = 0; k < maps.num_midpoints(); ++k) {
    // Composed maps (solver_levels.hpp) leave vertices that halve no coarse edge without
    // parents: their links come from their weights (point_links).
    if (!halves_coarse_edge(maps, k)) continue;
    const auto& ab = maps.midpoint_parents(cm, k);
    if (on_contact[ab[0]] && on_contact[ab[1]])
      midpoint[std::minmax(ab[0], ab[1])] = maps.num_coarse_vertices + k;
  }
  return midpoint;
}

/// The U_n links of the fine contact vertices that halve no coarse edge (composed maps: a chain
/// of midpoints along a coarse edge, or a vertex inside a coarse face): each with the coarse
/// vertices it interpolates and their weights.
template <int dim>
void point_links(const FoslsSpace<dim>& coarse, const FoslsSpace<dim>& fine,
                 const SimplexRefinementMaps<dim>& maps, std::vector<ContactLink>& links) {
  if (maps.composed_weights.empty()) return;
  for (int k = 0; k < maps.num_midpoints(); ++k) {
    const int v = maps.num_coarse_vertices + k;
    if (halves_coarse_edge(maps, k) || !fine.is_contact_vertex(v)) continue;
    const CoarseVertexWeights& w = maps.composed_weights[k];
    ContactLink& link = links.emplace_back();
    link.fine_un_mid = normal_u(fine, v);
    const std::array<int*, 3> coarse_un = {&link.coarse_un_a, &link.coarse_un_b, &link.coarse_un_c};
    const std::array<int*, 3> fine_un = {&link.fine_un_a, &link.fine_un_b, &link.fine_un_c};
    for (int i = 0; i < 3; ++i) {
      link.un_weight[i] = w.weight[i];
      if (w.vertex[i] < 0) continue;
      *coarse_un[i] = normal_u(coarse, w.vertex[i]);
      *fine_un[i] = normal_u(fine, w.vertex[i]);
    }
  }
}

}  // namespace

template <int dim>
std::vector<ContactLink> contact_links(const FoslsSpace<dim>& coarse, const FoslsSpace<dim>& fine,
                                       const SimplexRefinementMaps<dim>& maps,
                                       const SparseMatrix& prolongation) {
  const SimplexMesh<dim>& cm = coarse.mesh();
  const auto midpoint = contact_midpoints(coarse, maps);
  const auto children = contact_children(coarse, fine.mesh(), maps);
  // The coarse cells' interior DOFs carry 3D's flux moves, and 2D's only where levels were
  // skipped (an edge with more than two children): a uniform 2D hierarchy does without them.
  const bool moves_through_cells =
      dim == 3 || std::any_of(children.begin(), children.end(),
                              [](const std::vector<int>& kids) { return kids.size() > 2; });
  const std::vector<std::vector<int>> interior = moves_through_cells
                                                     ? interior_sigma_dofs(coarse, fine, maps)
                                                     : std::vector<std::vector<int>>{};
  std::vector<ContactLink> links;
  std::set<std::pair<int, int>> linked;  // coarse edges with their U_n link
  for (int F = 0; F < cm.num_facets(); ++F) {
    if (!coarse.is_contact_facet(F)) continue;
    const std::size_t first = links.size();
    for (const auto& ab : facet_edges(cm, F)) {
      const std::pair<int, int> key = std::minmax(ab[0], ab[1]);
      if (!linked.insert(key).second) continue;
      ContactLink& link = links.emplace_back();
      link.coarse_un_a = normal_u(coarse, ab[0]);
      link.coarse_un_b = normal_u(coarse, ab[1]);
      link.fine_un_a = normal_u(fine, ab[0]);
      link.fine_un_b = normal_u(fine, ab[1]);
      const auto mid = midpoint.find(key);
      link.fine_un_mid = mid == midpoint.end() ? -1 : normal_u(fine, mid->second);
    }
    const int coarse_sn = coarse.free_index(coarse.sigma_dof(F, 0));
    const std::vector<int>& kids = children[F];
    // 2D: the edge's U_n link carries its first S_n pair too.
    const std::size_t first_sn = dim == 2 ? first : links.size();
    const std::size_t pairs = (kids.size() + 1) / 2;
    // 3D's moves and those across more than two children go through the coarse cell's interior,
    // 2D's between two halves along their own path.
    const std::vector<int>* path =
        dim == 3 || pairs > 1 ? &interior[cm.facet_cells(F)[0]] : nullptr;
    for (std::size_t q = 0; q < kids.size(); q += 2) {
      ContactLink& link = dim == 2 && q == 0 ? links[first] : links.emplace_back();
      link.coarse_sn = coarse_sn;
      for (std::size_t k = 0; k < 2 && q + k < kids.size(); ++k) {
        link.fine_sn[k] = fine.free_index(fine.sigma_dof(kids[q + k], 0));
        link.sn_weight[k] = prolongation.coeff(link.fine_sn[k], coarse_sn);
      }
      if (link.fine_sn[0] >= 0 && link.fine_sn[1] >= 0)
        for (int k = 0; k < 2; ++k)
          link.flux_moves[k] = flux_move(fine, maps, kids[q + k], kids[q + 1 - k], path);
    }
    if (pairs > 1) make_partners(fine, maps, kids, *path, first_sn, pairs, links);
  }
  point_links(coarse, fine, maps, links);
  return links;
}

template std::vector<ContactLink> contact_links<2>(const FoslsSpace<2>&, const FoslsSpace<2>&,
                                                   const RefinementMaps&, const SparseMatrix&);
template std::vector<ContactLink> contact_links<3>(const FoslsSpace<3>&, const FoslsSpace<3>&,
                                                   const TetRefinementMaps&, const SparseMatrix&);

}  // namespace fosls
