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

/// The fine facets inside each coarse contact facet, in their pairs' order: in 2D the half at
/// the coarse edge's first end first (a kept edge alone), in 3D the quarters in fine order.
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
      auto& halves = children[e];
      const int first_end = coarse.mesh().edge(e)[0];
      if (halves.size() == 2 && fine.edge(halves[0])[0] != first_end &&
          fine.edge(halves[0])[1] != first_end)
        std::swap(halves[0], halves[1]);
    }
  return children;
}

/// 2D: the fine RT0 field that moves one unit of normal flux from boundary edge `from` to
/// boundary edge `to` (the two halves of one coarse contact edge) with zero divergence in every
/// fine triangle: the vector flux S·n_from leaves `from`'s triangle through its edge into the
/// interior of the coarse triangle, crosses the fine triangles between the halves and comes
/// out through `to`. Its first entry is `to`'s S_n, n_from·n_to (1 on a straight edge; the
/// tangential part, which S_t = 0 does not allow, is dropped on curved edges).
Move flux_move(const FoslsSpace<2>& space, const RefinementMaps& maps, int from, int to,
               const std::vector<int>&) {
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

/// 3D: one unit of normal flux taken off quarter `from` arrives on quarter `to` as
/// n_from · n_to of its S_n (the tangential rest falls on the fixed S_t), carried through the
/// fine faces inside the coarse tetrahedron (`interior`, their free σ DOFs), whose values the
/// truncation sets with the least energy (solvers/truncated_hierarchy.cpp).
Move flux_move(const FoslsSpace<3>& fine, const TetRefinementMaps&, int from, int to,
               const std::vector<int>& interior) {
  const TetMesh& m = fine.mesh();
  Move move;
  move.emplace_back(fine.free_index(fine.sigma_dof(to, 0)),
                    m.face_normal(from).dot(m.face_normal(to)));
  for (int dof : interior) move.emplace_back(dof, 0.0);
  return move;
}

/// 3D: the free σ DOFs of the fine faces inside each coarse tetrahedron under a contact face:
/// the way its flux moves go. (2D's moves find their own path.)
std::vector<std::vector<int>> interior_sigma_dofs(const FoslsSpace<3>& coarse,
                                                  const FoslsSpace<3>& fine,
                                                  const TetRefinementMaps& maps) {
  const TetMesh& cm = coarse.mesh();
  std::vector<char> under_contact(cm.num_tets(), 0);
  for (int f = 0; f < cm.num_faces(); ++f)
    if (coarse.is_contact_facet(f)) under_contact[cm.face_tets(f)[0]] = 1;
  std::vector<std::vector<int>> dofs(cm.num_tets());
  for (int f = 0; f < fine.mesh().num_faces(); ++f)
    if (const int t = maps.parent_tet_of_face[f]; t >= 0 && under_contact[t])
      for (int i = 0; i < 3; ++i)
        if (const int dof = fine.free_index(fine.sigma_dof(f, i)); dof >= 0) dofs[t].push_back(dof);
  return dofs;
}

/// Makes the last two links, a coarse facet's pairs, each other's partner: partner_factor[k][i]
/// = n_k · n_i from this link's child k to the partner's child i.
template <int dim>
void pair_up(const FoslsSpace<dim>& fine, const std::vector<int>& children,
             std::vector<ContactLink>& links) {
  const int n = static_cast<int>(links.size());
  const SimplexMesh<dim>& m = fine.mesh();
  for (int side = 0; side < 2; ++side) {
    ContactLink& link = links[n - 2 + side];
    link.partner = n - 1 - side;
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < 2; ++i)
        link.partner_factor[k][i] = m.facet_normal(children[2 * side + k])
                                        .dot(m.facet_normal(children[2 * (1 - side) + i]));
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
    // Composed maps (solver_levels.hpp) leave vertices off the contact boundary without parents.
    if (!halves_coarse_edge(maps, k)) continue;
    const auto& ab = maps.midpoint_parents(cm, k);
    if (on_contact[ab[0]] && on_contact[ab[1]])
      midpoint[std::minmax(ab[0], ab[1])] = maps.num_coarse_vertices + k;
  }
  return midpoint;
}

}  // namespace

template <int dim>
std::vector<ContactLink> contact_links(const FoslsSpace<dim>& coarse, const FoslsSpace<dim>& fine,
                                       const SimplexRefinementMaps<dim>& maps,
                                       const SparseMatrix& prolongation) {
  const SimplexMesh<dim>& cm = coarse.mesh();
  const auto midpoint = contact_midpoints(coarse, maps);
  const auto children = contact_children(coarse, fine.mesh(), maps);
  std::vector<std::vector<int>> interior;
  if constexpr (dim == 3) interior = interior_sigma_dofs(coarse, fine, maps);
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
    const std::vector<int> none;
    const std::vector<int>& path = dim == 3 ? interior[cm.facet_cells(F)[0]] : none;
    for (std::size_t q = 0; q < kids.size(); q += 2) {
      // 2D: the edge's U_n link carries its S_n pair too.
      ContactLink& link = dim == 2 ? links[first] : links.emplace_back();
      link.coarse_sn = coarse_sn;
      for (std::size_t k = 0; k < 2 && q + k < kids.size(); ++k) {
        link.fine_sn[k] = fine.free_index(fine.sigma_dof(kids[q + k], 0));
        link.sn_weight[k] = prolongation.coeff(link.fine_sn[k], coarse_sn);
      }
      if (link.fine_sn[0] >= 0 && link.fine_sn[1] >= 0)
        for (int k = 0; k < 2; ++k)
          link.flux_moves[k] = flux_move(fine, maps, kids[q + k], kids[q + 1 - k], path);
    }
    if (kids.size() == 4) pair_up(fine, kids, links);
  }
  return links;
}

template std::vector<ContactLink> contact_links<2>(const FoslsSpace<2>&, const FoslsSpace<2>&,
                                                   const RefinementMaps&, const SparseMatrix&);
template std::vector<ContactLink> contact_links<3>(const FoslsSpace<3>&, const FoslsSpace<3>&,
                                                   const TetRefinementMaps&, const SparseMatrix&);

}  // namespace fosls
