#include "fem/fosls_space.hpp"

#include <stdexcept>

namespace fosls {

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

  std::vector<char> dirichlet_vertex(nv, 0);
  std::vector<Point> averaged(nv, Point::Zero());
  std::vector<int> curve_of(nv, -1);
  for (int e = 0; e < ne; ++e) {
    int g = mesh.edge_group(e);
    if (g < 0) continue;
    const auto& pq = mesh.edge(e);
    switch (roles[g]) {
      case GroupRole::kDirichlet:
        dirichlet_vertex[pq[0]] = dirichlet_vertex[pq[1]] = 1;
        break;
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
    if (dirichlet_vertex[v]) {
      contact_vertex_[v] = 0;  // Dirichlet data win over the contact constraint
      roles_[u_dof(v, 0)] = roles_[u_dof(v, 1)] = DofRole::kFixed;
      continue;
    }
    if (!contact_vertex_[v]) continue;
    Point n = averaged[v].normalized();
    if (!vertex_normals.empty()) {
      n = vertex_normals[v].normalized();
    } else if (curve_of[v] >= 0) {
      // Exact normal of the arc, pointing out of the body like the edge normals do.
      Point radial = (mesh.vertex(v) - mesh.curves()[curve_of[v]].center).normalized();
      n = radial.dot(averaged[v]) >= 0 ? radial : Point(-radial);
    }
    vertex_normal_[v] = n;
    roles_[u_dof(v, 0)] = DofRole::kNormalU;
    roles_[u_dof(v, 1)] = DofRole::kFree;
  }

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
  rotation_.resize(num_dofs(), num_dofs());
  rotation_.setFromTriplets(q.begin(), q.end());

  full_to_free_.assign(num_dofs(), -1);
  for (int d = 0; d < num_dofs(); ++d)
    if (roles_[d] != DofRole::kFixed) {
      full_to_free_[d] = static_cast<int>(free_to_full_.size());
      free_to_full_.push_back(d);
    }
}

}  // namespace fosls
