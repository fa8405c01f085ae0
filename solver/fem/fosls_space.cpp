#include "fem/fosls_space.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include "fem/contact_frame.hpp"

namespace fosls {

template <int dim>
struct FoslsSpace<dim>::VertexMarks {
  std::vector<int> prescribed;     ///< bit c: u_c is Dirichlet data at the vertex
  std::vector<char> contact;       ///< the vertex lies on a contact facet
  std::vector<Vec<dim>> averaged;  ///< sum of the normals of the contact facets at the vertex
  std::vector<int> curve_of;       ///< 2D: the arc of a contact edge at the vertex (−1: none)
};

template <int dim>
FoslsSpace<dim>::FoslsSpace(const MeshType& mesh, const std::vector<BoundaryRole>& groups,
                            const std::vector<Vec<dim>>& vertex_normals)
    : mesh_(&mesh) {
  if (groups.size() != mesh.group_names().size())
    throw std::logic_error("FoslsSpace: one role per boundary group expected");
  roles_.assign(num_dofs(), DofRole::kFree);
  contact_facet_.assign(mesh.num_facets(), 0);
  set_vertex_roles(mark_boundary_facets(groups), vertex_normals);
  number_free_dofs();
}

template <int dim>
typename FoslsSpace<dim>::VertexMarks FoslsSpace<dim>::mark_boundary_facets(
    const std::vector<BoundaryRole>& groups) {
  const int nv = mesh_->num_vertices();
  constexpr int every = (1 << dim) - 1;
  VertexMarks m;
  m.prescribed.assign(nv, 0);
  m.contact.assign(nv, 0);
  m.averaged.assign(nv, Vec<dim>::Zero());
  m.curve_of.assign(nv, -1);
  for (int f = 0; f < mesh_->num_facets(); ++f) {
    const int g = mesh_->facet_group(f);
    if (g < 0) continue;
    switch (groups[g].role) {
      case GroupRole::kDirichlet: {
        const int bits = groups[g].prescribed & every;
        for (int v : mesh_->facet(f)) m.prescribed[v] |= bits;
        for (int i = 0; i < dim; ++i)  // a free component's traction is zero (a roller)
          if (!(bits & (1 << i))) roles_[sigma_dof(f, i)] = DofRole::kFixed;
        break;
      }
      case GroupRole::kNeumann:
        for (int i = 0; i < dim; ++i) roles_[sigma_dof(f, i)] = DofRole::kFixed;
        break;
      case GroupRole::kContact:
        if (dim == 3 && groups[g].frictional)
          throw std::invalid_argument(
              "friction in 3D: its tangential bound |S_t| ≤ s̄ is a disc, not the box that the "
              "solvers' bounds are; 3D contact is frictionless so far");
        contact_facet_[f] = 1;
        roles_[sigma_dof(f, 0)] = DofRole::kNormalS;
        for (int i = 1; i < dim; ++i)  // σ_nt = 0, or bounded with friction
          roles_[sigma_dof(f, i)] = groups[g].frictional ? DofRole::kTangentialS : DofRole::kFixed;
        for (int v : mesh_->facet(f)) {
          m.contact[v] = 1;
          m.averaged[v] += mesh_->facet_normal(f);
          if constexpr (dim == 2)
            if (mesh_->edge_curve(f) >= 0) m.curve_of[v] = mesh_->edge_curve(f);
        }
        break;
    }
  }
  return m;
}

template <int dim>
Vec<dim> FoslsSpace<dim>::contact_normal(int v, const VertexMarks& marks,
                                         const std::vector<Vec<dim>>& vertex_normals) const {
  if (!vertex_normals.empty()) return vertex_normals[v].normalized();
  if constexpr (dim == 2) {
    if (const int curve = marks.curve_of[v]; curve >= 0) {
      // Exact normal of the arc, pointing out of the body like the edge normals do. (3D takes
      // the mean of the faces' normals on a sphere too: docs/method.md §11.)
      const Point radial = (mesh_->vertex(v) - mesh_->curves()[curve].center).normalized();
      return radial.dot(marks.averaged[v]) >= 0 ? radial : Point(-radial);
    }
  }
  return marks.averaged[v].normalized();
}

template <int dim>
void FoslsSpace<dim>::set_vertex_roles(const VertexMarks& marks,
                                       const std::vector<Vec<dim>>& vertex_normals) {
  constexpr int every = (1 << dim) - 1;
  frame_of_vertex_.assign(mesh_->num_vertices(), -1);
  for (int v = 0; v < mesh_->num_vertices(); ++v) {
    const int bits = marks.prescribed[v];
    if (bits == every) {  // Dirichlet data win over the contact constraint
      for (int c = 0; c < dim; ++c) roles_[u_dof(v, c)] = DofRole::kFixed;
      continue;
    }
    if (marks.contact[v]) {
      // Where rollers meet the contact boundary (symmetry planes through the contact zone) the
      // prescribed axes become the frame's tangents, fixed, and U_n ≤ g stays.
      const Mat<dim> frame = roller_frame<dim>(contact_normal(v, marks, vertex_normals), bits);
      if (!frame.isZero()) {
        frame_of_vertex_[v] = static_cast<int>(frames_.size());
        frames_.push_back(frame);
        roles_[u_dof(v, 0)] = DofRole::kNormalU;
        for (int k = 1; k <= std::popcount(static_cast<unsigned>(bits)); ++k)
          roles_[u_dof(v, k)] = DofRole::kFixed;
        continue;
      }
    }
    for (int c = 0; c < dim; ++c)  // an oblique roller cannot be both: its data win
      if (bits & (1 << c)) roles_[u_dof(v, c)] = DofRole::kFixed;
  }
}

template <int dim>
void FoslsSpace<dim>::number_free_dofs() {
  full_to_free_.assign(num_dofs(), -1);
  // Reserved exactly: grown by push_back it kept up to twice its size on every level.
  free_to_full_.reserve(num_dofs() - std::count(roles_.begin(), roles_.end(), DofRole::kFixed));
  for (int d = 0; d < num_dofs(); ++d)
    if (roles_[d] != DofRole::kFixed) {
      full_to_free_[d] = static_cast<int>(free_to_full_.size());
      free_to_full_.push_back(d);
    }
}

template <int dim>
std::array<int, FoslsSpace<dim>::kCellDofs> FoslsSpace<dim>::cell_dofs(int t) const {
  std::array<int, kCellDofs> d;
  for (int k = 0; k <= dim; ++k)
    for (int c = 0; c < dim; ++c) {
      d[dim * k + c] = u_dof(mesh_->cell(t)[k], c);
      d[dim * (dim + 1) + dim * k + c] = sigma_dof(mesh_->cell_facet(t, k), c);
    }
  return d;
}

template <int dim>
Eigen::SparseMatrix<double> FoslsSpace<dim>::rotation() const {
  // Formed when asked for (setting up transfers, output), not kept: it is as large as a few
  // vectors of the level and nothing in a solve's iteration uses it.
  std::vector<Eigen::Triplet<double>> q;
  q.reserve(num_dofs() + dim * (dim - 1) * frames_.size());
  auto block = [&q](int d, const Mat<dim>& frame) {
    for (int c = 0; c < dim; ++c)
      for (int r = 0; r < dim; ++r) q.emplace_back(d + r, d + c, frame(r, c));
  };
  auto identity = [&q](int d) {
    for (int r = 0; r < dim; ++r) q.emplace_back(d + r, d + r, 1.0);
  };
  for (int v = 0; v < mesh_->num_vertices(); ++v)
    is_contact_vertex(v) ? block(u_dof(v, 0), vertex_frame(v)) : identity(u_dof(v, 0));
  for (int f = 0; f < mesh_->num_facets(); ++f)
    is_contact_facet(f) ? block(sigma_dof(f, 0), normal_frame<dim>(mesh_->facet_normal(f)))
                        : identity(sigma_dof(f, 0));
  Eigen::SparseMatrix<double> rotation(num_dofs(), num_dofs());
  rotation.setFromTriplets(q.begin(), q.end());
  return rotation;
}

template class FoslsSpace<2>;
template class FoslsSpace<3>;

}  // namespace fosls
