#pragma once
// The 3D space X_j = P1(T_j)³ × RT0(T_j)³ of one level with its boundary roles (docs/method.md
// §11): stage 1 of the 3D track, linear elasticity with Dirichlet and Neumann groups.

#include <vector>

#include "fem/fosls_space.hpp"
#include "mesh/tet_mesh.hpp"

namespace fosls {

/// DOF layout: u_c at vertex v is 3v + c; σ row i on face f is 3·n_v + 3f + i (the flux
/// ∫_f σ_i·n_f through the face with its global normal).
class TetSpace {
 public:
  /// `roles[g]` for mesh group g: kDirichlet (u fixed) or kNeumann (σ·n fixed); ungrouped
  /// boundary faces are traction free. Throws std::invalid_argument for other roles.
  TetSpace(const TetMesh& mesh, const std::vector<GroupRole>& roles);

  const TetMesh& mesh() const { return *mesh_; }
  int num_dofs() const { return 3 * mesh_->num_vertices() + 3 * mesh_->num_faces(); }
  int u_dof(int v, int c) const { return 3 * v + c; }
  int sigma_dof(int f, int i) const { return 3 * mesh_->num_vertices() + 3 * f + i; }
  bool fixed(int dof) const { return fixed_[dof] != 0; }
  /// The 24 DOFs of tetrahedron t: u of its vertices (3k + c), then σ of its faces
  /// (12 + 3k + i).
  std::array<int, 24> tet_dofs(int t) const;

  int num_free() const { return static_cast<int>(free_to_full_.size()); }
  const std::vector<int>& free_to_full() const { return free_to_full_; }
  int free_index(int dof) const { return full_to_free_[dof]; }

 private:
  const TetMesh* mesh_;
  std::vector<char> fixed_;
  std::vector<int> free_to_full_, full_to_free_;
};

}  // namespace fosls
