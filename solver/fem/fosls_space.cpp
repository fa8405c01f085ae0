#include "fem/fosls_space.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fosls {

int prescribed_components(GroupRole role) {
  switch (role) {
    case GroupRole::kDirichlet:
      return 3;
    case GroupRole::kDirichletX:
      return 1;
    case GroupRole::kDirichletY:
      return 2;
    case GroupRole::kNeumann:
    case GroupRole::kContact:
      break;
  }
  return 0;
}

FoslsSpace::FoslsSpace(const Mesh& mesh, const std::vector<GroupRole>& roles,
                       const std::vector<Point>& vertex_normals)
    : mesh_(&mesh) {
  const int nv = mesh.num_vertices(), ne = mesh.num_edges();
  if (roles.size() != mesh.group_names().size())
    throw std::logic_error("FoslsSpace: one role per boundary group expected");
  roles_.assign(num_dofs(), DofRole::kFree);
  contact_vertex_.assign(nv, 0);
  contact_edge_.assign(ne, 0);
  vertex_normal_.assign(nv, Point::Zero());

  std::vector<int> prescribed(nv, 0);  // bit c: u_c is Dirichlet data at the vertex
  std::vector<Point> averaged(nv, Point::Zero());
  std::vector<int> curve_of(nv, -1);
  for (int e = 0; e < ne; ++e) {
    int g = mesh.edge_group(e);
    if (g < 0) continue;
    const auto& pq = mesh.edge(e);
    switch (roles[g]) {
      case GroupRole::kDirichlet:
        prescribed[pq[0]] |= 3;
        prescribed[pq[1]] |= 3;
        break;
      case GroupRole::kDirichletX:
      case GroupRole::kDirichletY: {
        const int c = roles[g] == GroupRole::kDirichletX ? 0 : 1;
        prescribed[pq[0]] |= 1 << c;
        prescribed[pq[1]] |= 1 << c;
        roles_[sigma_dof(e, 1 - c)] = DofRole::kFixed;  // the free component's traction is 0
        break;
      }
      case GroupRole::kNeumann:
        roles_[sigma_dof(e, 0)] = roles_[sigma_dof(e, 1)] = DofRole::kFixed;
        break;
      case GroupRole::kContact:
        contact_edge_[e] = 1;
        roles_[sigma_dof(e, 0)] = DofRole::kNormalS;
        roles_[sigma_dof(e, 1)] = DofRole::kFixed;  // σ_nt = 0
        for (int v : pq) {
          contact_vertex_[v] = 1;
          averaged[v] += mesh.edge_normal(e);
          if (mesh.edge_curve(e) >= 0) curve_of[v] = mesh.edge_curve(e);
        }
        break;
    }
  }
  for (int v = 0; v < nv; ++v) {
    if (prescribed[v] == 3) {
      contact_vertex_[v] = 0;  // Dirichlet data win over the contact constraint
      roles_[u_dof(v, 0)] = roles_[u_dof(v, 1)] = DofRole::kFixed;
      continue;
    }
    if (!contact_vertex_[v]) {
      for (int c = 0; c < 2; ++c)
        if (prescribed[v] & (1 << c)) roles_[u_dof(v, c)] = DofRole::kFixed;
      continue;
    }
    Point n = averaged[v].normalized();
    if (!vertex_normals.empty()) {
      n = vertex_normals[v].normalized();
    } else if (curve_of[v] >= 0) {
      // Exact normal of the arc, pointing out of the body like the edge normals do.
      Point radial = (mesh.vertex(v) - mesh.curves()[curve_of[v]].center).normalized();
      n = radial.dot(averaged[v]) >= 0 ? radial : Point(-radial);
    }
    if (prescribed[v]) {
      // Where a roller meets the contact boundary (a symmetry plane through the contact zone)
      // the prescribed axis is the tangent t = (−n_y, n_x): U_t is prescribed and U_n ≤ g
      // stays. An oblique roller cannot be both; its Dirichlet data win.
      const int c = prescribed[v] == 1 ? 0 : 1;
      if (std::abs(n[c]) > 1e-12) {
        contact_vertex_[v] = 0;
        roles_[u_dof(v, c)] = DofRole::kFixed;
        continue;
      }
    }
    vertex_normal_[v] = n;
    roles_[u_dof(v, 0)] = DofRole::kNormalU;
    roles_[u_dof(v, 1)] = prescribed[v] ? DofRole::kFixed : DofRole::kFree;
  }

  full_to_free_.assign(num_dofs(), -1);
  // Reserved exactly: grown by push_back it kept up to twice its size on every level.
  free_to_full_.reserve(num_dofs() - std::count(roles_.begin(), roles_.end(), DofRole::kFixed));
  for (int d = 0; d < num_dofs(); ++d)
    if (roles_[d] != DofRole::kFixed) {
      full_to_free_[d] = static_cast<int>(free_to_full_.size());
      free_to_full_.push_back(d);
    }
}

Eigen::SparseMatrix<double> FoslsSpace::rotation() const {
  // Formed when asked for (setting up transfers, output), not kept: it is as large as a few
  // vectors of the level and nothing in a solve's iteration uses it.
  const Mesh& mesh = *mesh_;
  const int nv = mesh.num_vertices(), ne = mesh.num_edges();
  std::vector<Eigen::Triplet<double>> q;
  q.reserve(num_dofs() + 2 * nv);
  auto block = [&q](int d, const Point& n) {
    // Columns: (n, t) with t = (−n_y, n_x).
    q.emplace_back(d, d, n.x());
    q.emplace_back(d + 1, d, n.y());
    q.emplace_back(d, d + 1, -n.y());
    q.emplace_back(d + 1, d + 1, n.x());
  };
  for (int v = 0; v < nv; ++v) {
    if (contact_vertex_[v]) {
      block(u_dof(v, 0), vertex_normal_[v]);
    } else {
      q.emplace_back(u_dof(v, 0), u_dof(v, 0), 1.0);
      q.emplace_back(u_dof(v, 1), u_dof(v, 1), 1.0);
    }
  }
  for (int e = 0; e < ne; ++e) {
    if (contact_edge_[e]) {
      block(sigma_dof(e, 0), mesh.edge_normal(e));
    } else {
      q.emplace_back(sigma_dof(e, 0), sigma_dof(e, 0), 1.0);
      q.emplace_back(sigma_dof(e, 1), sigma_dof(e, 1), 1.0);
    }
  }
  Eigen::SparseMatrix<double> rotation(num_dofs(), num_dofs());
  rotation.setFromTriplets(q.begin(), q.end());
  return rotation;
}

}  // namespace fosls
