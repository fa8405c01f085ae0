#include "assembly/tet_hierarchy.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "assembly/patch_blocks.hpp"
#include "fem/simplex_element.hpp"

namespace fosls {

Eigen::SparseMatrix<double> tet_prolongation(const TetMesh& coarse, const TetMesh& fine,
                                             const TetRefinementMaps& maps) {
  const int ncv = coarse.num_vertices(), nfv = fine.num_vertices();
  auto sc = [ncv](int f, int i) { return 3 * ncv + 3 * f + i; };
  auto sf = [nfv](int f, int i) { return 3 * nfv + 3 * f + i; };
  std::vector<Eigen::Triplet<double>> t;
  for (int v = 0; v < nfv; ++v)
    for (int c = 0; c < 3; ++c) {
      if (v < ncv) {
        t.emplace_back(3 * v + c, 3 * v + c, 1.0);
      } else {
        for (int end : maps.midpoint_ends[v - ncv]) t.emplace_back(3 * v + c, 3 * end + c, 0.5);
      }
    }
  for (int f = 0; f < fine.num_faces(); ++f) {
    if (const int parent = maps.parent_face[f]; parent >= 0) {
      // RT0's normal component is constant on a face: a fine face carries its share of the flux.
      const double share = maps.parent_face_share[f] *
                           (fine.face_normal(f).dot(coarse.face_normal(parent)) > 0 ? 1 : -1);
      for (int i = 0; i < 3; ++i) t.emplace_back(sf(f, i), sc(parent, i), share);
      continue;
    }
    const int tc = maps.parent_tet_of_face[f];
    const SimplexElement<3> e(coarse, tc);
    const Point3 scaled_normal = fine.face_area(f) * fine.face_normal(f);
    for (int k = 0; k < 4; ++k) {
      // ψ_k is linear: its flux through a plane face is its value at the centroid times |f| n_f.
      const double flux = e.rt0(k, fine.face_centroid(f)).dot(scaled_normal);
      for (int i = 0; i < 3; ++i) t.emplace_back(sf(f, i), sc(coarse.tet_face(tc, k), i), flux);
    }
  }
  Eigen::SparseMatrix<double> p(3 * nfv + 3 * fine.num_faces(), 3 * ncv + 3 * coarse.num_faces());
  p.setFromTriplets(t.begin(), t.end());
  return p;
}

std::vector<std::vector<int>> tet_vertex_patches(const FoslsSpace<3>& space,
                                                 std::array<int, 2>* split) {
  const TetMesh& mesh = space.mesh();
  const auto faces = mesh.vertex_faces();
  // The vertex pairs of the tetrahedra, sorted: the graph the two blocks are separated in.
  std::vector<std::array<int, 2>> edges;
  for (int t = 0; t < mesh.num_tets(); ++t)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        edges.push_back(
            {std::min(mesh.tet(t)[i], mesh.tet(t)[j]), std::max(mesh.tet(t)[i], mesh.tet(t)[j])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<Eigen::VectorXd> points;
  for (int v = 0; v < mesh.num_vertices(); ++v) points.emplace_back(mesh.vertex(v));
  const VertexBlocks blocks = two_vertex_blocks(points, edges);
  std::vector<std::vector<int>> patches;
  for (int k = 0; k < mesh.num_vertices(); ++k) {
    for (int b = 0; b < 2; ++b)
      if (split && k == blocks.ends[b]) (*split)[b] = static_cast<int>(patches.size());
    const int v = blocks.order[k];
    std::vector<int> p;
    auto take = [&](int dof) {
      if (const int f = space.free_index(dof); f >= 0) p.push_back(f);
    };
    for (int c = 0; c < 3; ++c) take(space.u_dof(v, c));
    for (int f : faces[v])
      for (int i = 0; i < 3; ++i) take(space.sigma_dof(f, i));
    if (!p.empty()) patches.push_back(std::move(p));
  }
  for (int b = 0; b < 2; ++b)
    if (split && blocks.ends[b] == mesh.num_vertices())
      (*split)[b] = static_cast<int>(patches.size());
  return patches;
}

namespace {

/// The free σ DOFs of the fine faces inside one coarse tetrahedron: the way a flux move goes.
std::vector<int> interior_sigma_dofs(const FoslsSpace<3>& fine, const std::vector<int>& faces) {
  std::vector<int> dofs;
  for (int f : faces)
    for (int i = 0; i < 3; ++i)
      if (const int dof = fine.free_index(fine.sigma_dof(f, i)); dof >= 0) dofs.push_back(dof);
  return dofs;
}

/// 2D's flux move (ContactLink::flux_moves) on a coarse contact face: one unit of normal flux
/// taken off quarter `from` arrives on quarter `to` as n_from · n_to of its S_n (the tangential
/// rest falls on the fixed S_t), carried through the fine faces inside the coarse tetrahedron,
/// whose values the truncation sets with the least energy.
std::vector<std::pair<int, double>> flux_move(const FoslsSpace<3>& fine, int from, int to,
                                              const std::vector<int>& path) {
  const TetMesh& m = fine.mesh();
  std::vector<std::pair<int, double>> move;
  move.emplace_back(fine.free_index(fine.sigma_dof(to, 0)),
                    m.face_normal(from).dot(m.face_normal(to)));
  for (int dof : path) move.emplace_back(dof, 0.0);
  return move;
}

/// Makes the last two links, a coarse face's quarters 0–1 and 2–3, each other's partner.
void pair_up(const FoslsSpace<3>& fine, const std::vector<int>& quarters,
             std::vector<ContactLink>& links) {
  const int n = static_cast<int>(links.size());
  const TetMesh& m = fine.mesh();
  for (int side = 0; side < 2; ++side) {
    ContactLink& link = links[n - 2 + side];
    link.partner = n - 1 - side;
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < 2; ++i)
        link.partner_factor[k][i] =
            m.face_normal(quarters[2 * side + k]).dot(m.face_normal(quarters[2 * (1 - side) + i]));
  }
}

/// Contact links between a level and the one below (docs/method.md §4.3 in 3D): one per coarse
/// contact edge for U_n (its ends and the fine midpoint, interpolated with ½, ½ as in 2D) and
/// two per coarse contact face for S_n (its four quarters, each with weight ¼), so that the 2D
/// projections of the defect obstacle apply unchanged.
std::vector<ContactLink> tet_contact_links(const FoslsSpace<3>& coarse, const FoslsSpace<3>& fine,
                                           const TetRefinementMaps& maps,
                                           const SparseMatrix& prolongation) {
  const TetMesh& cm = coarse.mesh();
  std::map<std::pair<int, int>, int> midpoint;
  for (std::size_t k = 0; k < maps.midpoint_ends.size(); ++k)
    midpoint[{maps.midpoint_ends[k][0], maps.midpoint_ends[k][1]}] =
        maps.num_coarse_vertices + static_cast<int>(k);
  auto normal_u = [](const FoslsSpace<3>& s, int v) {
    return s.is_contact_vertex(v) ? s.free_index(s.u_dof(v, 0)) : -1;
  };
  std::vector<ContactLink> links;
  std::set<std::pair<int, int>> edges;
  std::vector<std::vector<int>> quarters(cm.num_faces()), inside(cm.num_tets());
  for (int f = 0; f < fine.mesh().num_faces(); ++f) {
    if (const int parent = maps.parent_face[f]; parent >= 0 && coarse.is_contact_facet(parent))
      quarters[parent].push_back(f);
    if (const int t = maps.parent_tet_of_face[f]; t >= 0) inside[t].push_back(f);
  }
  for (int F = 0; F < cm.num_faces(); ++F) {
    if (!coarse.is_contact_facet(F)) continue;
    const auto& v = cm.face(F);
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, int> e = std::minmax(v[k], v[(k + 1) % 3]);
      if (!edges.insert(e).second) continue;
      ContactLink link;
      link.coarse_un_a = normal_u(coarse, e.first);
      link.coarse_un_b = normal_u(coarse, e.second);
      link.fine_un_a = normal_u(fine, e.first);
      link.fine_un_b = normal_u(fine, e.second);
      link.fine_un_mid = normal_u(fine, midpoint.at(e));
      links.push_back(link);
    }
    const int coarse_sn = coarse.free_index(coarse.sigma_dof(F, 0));
    const std::vector<int> path = interior_sigma_dofs(fine, inside[cm.face_tets(F)[0]]);
    for (std::size_t q = 0; q + 1 < quarters[F].size(); q += 2) {
      ContactLink link;
      link.coarse_sn = coarse_sn;
      for (int k = 0; k < 2; ++k) {
        link.fine_sn[k] = fine.free_index(fine.sigma_dof(quarters[F][q + k], 0));
        link.sn_weight[k] = prolongation.coeff(link.fine_sn[k], coarse_sn);
      }
      for (int k = 0; k < 2; ++k)
        link.flux_moves[k] = flux_move(fine, quarters[F][q + k], quarters[F][q + 1 - k], path);
      links.push_back(link);
    }
    if (quarters[F].size() == 4) pair_up(fine, quarters[F], links);
  }
  return links;
}

/// Free DOFs of the tetrahedra touching the contact boundary, sorted: the strip smoother's
/// block (docs/method.md §4.1). One layer, not 2D's two: in 3D the strip is a slab whose exact
/// solve dominated the solve with two (docs/performance.md, "3D").
std::vector<int> tet_contact_strip(const FoslsSpace<3>& space) {
  const TetMesh& mesh = space.mesh();
  std::vector<char> near(mesh.num_vertices(), 0);
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (space.is_contact_facet(f))
      for (int v : mesh.face(f)) near[v] = 1;
  auto touches = [&](int t) {
    const auto& v = mesh.tet(t);
    return near[v[0]] || near[v[1]] || near[v[2]] || near[v[3]];
  };
  std::vector<int> strip;
  for (int t = 0; t < mesh.num_tets(); ++t)
    if (touches(t))
      for (int dof : space.cell_dofs(t))
        if (const int f = space.free_index(dof); f >= 0) strip.push_back(f);
  std::sort(strip.begin(), strip.end());
  strip.erase(std::unique(strip.begin(), strip.end()), strip.end());
  return strip;
}

}  // namespace

TetDiscretization::TetDiscretization(TetHierarchy meshes, ProblemData<3> data)
    : meshes_(std::move(meshes)), data_(std::move(data)) {
  for (const TetMesh& m : meshes_.meshes)
    spaces_.push_back(std::make_unique<FoslsSpace<3>>(m, data_.boundary_roles()));
  assembler_ = std::make_unique<FoslsAssembler<3>>(*spaces_.back(), data_);
  problem_ = assembler_->assemble_system();
}

LevelHierarchy TetDiscretization::build_level_hierarchy() const {
  LevelHierarchy h;
  h.levels.resize(meshes_.num_levels());
  for (int j = 0; j < meshes_.num_levels(); ++j) {
    const FoslsSpace<3>& fine = *spaces_[j];
    Level& level = h.levels[j];
    level.num_dofs = fine.num_free();
    level.patches = tet_vertex_patches(fine, &level.patch_split);
    level.contact_strip = tet_contact_strip(fine);
    level.block_factorization = BlockFactorization::held_rows;
    if (j == 0) continue;
    const FoslsSpace<3>& coarse = *spaces_[j - 1];
    // In both levels' rotated coordinates (contact frames), like the 2D free_prolongation.
    const Eigen::SparseMatrix<double> full =
        fine.rotation().transpose() *
        tet_prolongation(coarse.mesh(), fine.mesh(), meshes_.maps[j]) * coarse.rotation();
    std::vector<Eigen::Triplet<double>> t;
    for (int col = 0; col < full.outerSize(); ++col) {
      const int fc = coarse.free_index(col);
      if (fc < 0) continue;
      for (Eigen::SparseMatrix<double>::InnerIterator it(full, col); it; ++it)
        if (const int fr = fine.free_index(static_cast<int>(it.row()));
            fr >= 0 && std::abs(it.value()) > 1e-14)
          t.emplace_back(fr, fc, it.value());
    }
    level.prolongation.resize(fine.num_free(), coarse.num_free());
    level.prolongation.setFromTriplets(t.begin(), t.end());
    level.links = tet_contact_links(coarse, fine, meshes_.maps[j], level.prolongation);
  }
  return h;
}

}  // namespace fosls
