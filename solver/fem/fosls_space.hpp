#pragma once
// The discrete space X_j = P1(T_j)^d × RT0(T_j)^d of one level with its boundary roles
// (docs/method.md §3 and §11), for triangles (dim = 2) and tetrahedra (dim = 3): DOF numbering,
// rotated contact coordinates, fixed DOFs and bounded DOFs.

#include <Eigen/Sparse>
#include <array>
#include <vector>

#include "mesh/simplex_mesh.hpp"

namespace fosls {

/// Role of a boundary group in the discrete problem.
enum class GroupRole { kDirichlet, kNeumann, kContact };

/// Every displacement component (BoundaryRole::prescribed).
constexpr int kEveryComponent = -1;

/// What a boundary group makes of the DOFs on it.
struct BoundaryRole {
  GroupRole role = GroupRole::kNeumann;
  /// kDirichlet: the displacement components it prescribes, bit c for u_c. A component left
  /// free has zero traction (a roller, or a symmetry plane: bit 0 alone on a plane x = const).
  int prescribed = kEveryComponent;
  /// kContact: S_t free and bounded by the slip bound (friction, docs/method.md §8; 2D only)
  /// instead of fixed at σ_nt = 0.
  bool frictional = false;
};

/// How a DOF enters the quadratic program.
enum class DofRole : unsigned char {
  kFree,         ///< unconstrained
  kFixed,        ///< essential: Dirichlet u, Neumann σ flux, tangential σ on contact facets
  kNormalU,      ///< U_n at a contact vertex: U_n ≤ g
  kNormalS,      ///< S_n on a contact facet: S_n ≤ 0
  kTangentialS,  ///< S_t on a frictional contact edge: |S_t| ≤ s̄ (docs/method.md §8)
};

/// Full DOF vector layout: u_c at vertex v is d·v + c; σ row i on facet f is d·n_v + d·f + i
/// (the flux ∫_f σ_i·n_f through the facet with its global normal). At a contact vertex the d
/// DOFs hold (U_n, U_t…) in the vertex's frame (contact_frame.hpp), on a contact facet
/// (S_n, S_t…) in the frame of its normal.
template <int dim>
class FoslsSpace {
 public:
  using MeshType = SimplexMesh<dim>;
  /// DOFs of a cell: u of its d + 1 vertices (d·k + c), then σ of its facets (d(d + 1) + d·k + i).
  static constexpr int kCellDofs = 2 * dim * (dim + 1);

  /// `groups[g]` says what mesh group g does; ungrouped boundary facets are traction free.
  /// `vertex_normals` gives the constraint direction at each contact vertex (ignored elsewhere;
  /// empty = the exact normal of a 2D arc, else the normalised sum of the adjacent contact
  /// facets' normals). Throws std::invalid_argument for a frictional group in 3D.
  FoslsSpace(const MeshType& mesh, const std::vector<BoundaryRole>& groups,
             const std::vector<Vec<dim>>& vertex_normals = {});

  const MeshType& mesh() const { return *mesh_; }
  int num_dofs() const { return dim * mesh_->num_vertices() + dim * mesh_->num_facets(); }
  int u_dof(int v, int c) const { return dim * v + c; }
  int sigma_dof(int f, int i) const { return dim * mesh_->num_vertices() + dim * f + i; }
  std::array<int, kCellDofs> cell_dofs(int t) const;

  DofRole role(int dof) const { return roles_[dof]; }
  bool fixed(int dof) const { return roles_[dof] == DofRole::kFixed; }
  bool is_contact_vertex(int v) const { return frame_of_vertex_[v] >= 0; }
  bool is_contact_facet(int f) const { return contact_facet_[f] != 0; }
  bool is_contact_edge(int e) const requires(dim == 2) { return is_contact_facet(e); }
  /// The frame (n, t…) of a contact vertex: its columns, n the constraint direction.
  const Mat<dim>& vertex_frame(int v) const { return frames_[frame_of_vertex_[v]]; }
  /// Constraint direction n_v at a contact vertex.
  Vec<dim> vertex_normal(int v) const { return vertex_frame(v).col(0); }

  /// Rotation Q with x_cartesian = Q x_rotated (orthogonal, d×d blocks at contact DOFs),
  /// formed on each call.
  Eigen::SparseMatrix<double> rotation() const;

  int num_free() const { return static_cast<int>(free_to_full_.size()); }
  const std::vector<int>& free_to_full() const { return free_to_full_; }
  /// Free index of a full DOF, -1 for fixed DOFs.
  int free_index(int dof) const { return full_to_free_[dof]; }

 private:
  /// What the boundary groups say about each vertex (the constructor's first step).
  struct VertexMarks;
  /// Roles of the facets' DOFs from their group's role; contact facets marked.
  VertexMarks mark_boundary_facets(const std::vector<BoundaryRole>& groups);
  /// Roles of the vertices' DOFs and the contact frames, from the marks.
  void set_vertex_roles(const VertexMarks& marks, const std::vector<Vec<dim>>& vertex_normals);
  /// The normal of contact vertex v: given, a 2D arc's exact one, or the facets' average.
  Vec<dim> contact_normal(int v, const VertexMarks& marks,
                          const std::vector<Vec<dim>>& vertex_normals) const;
  /// The free DOFs (all but the fixed ones), numbered in DOF order.
  void number_free_dofs();

  const MeshType* mesh_;
  std::vector<DofRole> roles_;
  std::vector<char> contact_facet_;
  /// Per vertex the index of its frame in frames_, -1 off the contact boundary: only contact
  /// vertices pay for a frame.
  std::vector<int> frame_of_vertex_;
  std::vector<Mat<dim>> frames_;
  std::vector<int> free_to_full_, full_to_free_;
};

extern template class FoslsSpace<2>;
extern template class FoslsSpace<3>;

}  // namespace fosls
