#include "fem/tet_space.hpp"

#include <stdexcept>

namespace fosls {

TetSpace::TetSpace(const TetMesh& mesh, const std::vector<GroupRole>& roles) : mesh_(&mesh) {
  if (roles.size() != mesh.group_names().size())
    throw std::logic_error("TetSpace: one role per boundary group expected");
  fixed_.assign(num_dofs(), 0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int g = mesh.face_group(f);
    if (g < 0) continue;
    if (roles[g] == GroupRole::kDirichlet) {
      for (int v : mesh.face(f))
        for (int c = 0; c < 3; ++c) fixed_[u_dof(v, c)] = 1;
    } else if (roles[g] == GroupRole::kNeumann) {
      for (int i = 0; i < 3; ++i) fixed_[sigma_dof(f, i)] = 1;
    } else {
      throw std::invalid_argument("3D: Dirichlet and Neumann groups only (stage 1)");
    }
  }
  full_to_free_.assign(num_dofs(), -1);
  for (int d = 0; d < num_dofs(); ++d)
    if (!fixed_[d]) {
      full_to_free_[d] = static_cast<int>(free_to_full_.size());
      free_to_full_.push_back(d);
    }
}

std::array<int, 24> TetSpace::tet_dofs(int t) const {
  std::array<int, 24> d;
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) {
      d[3 * k + c] = u_dof(mesh_->tet(t)[k], c);
      d[12 + 3 * k + c] = sigma_dof(mesh_->tet_face(t, k), c);
    }
  return d;
}

}  // namespace fosls
