#include "assembly/discretization.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/contact_links.hpp"
#include "assembly/contact_strip.hpp"
#include "assembly/vertex_patches.hpp"
#include "fem/transfer.hpp"

namespace fosls {

template <int dim>
Discretization<dim>::Discretization(SimplexHierarchy<dim> meshes, ProblemData<dim> data,
                                    const Deadline& deadline)
    : meshes_(std::move(meshes)), data_(std::make_unique<ProblemData<dim>>(std::move(data))) {
  const auto roles = data_->boundary_roles();
  for (const SimplexMesh<dim>& m : meshes_.meshes) {
    deadline.check("building the finite element spaces");
    spaces_.push_back(
        std::make_unique<FoslsSpace<dim>>(m, roles, obstacle_vertex_normals(m, *data_)));
  }
  assembler_ = std::make_unique<FoslsAssembler<dim>>(*spaces_.back(), *data_);
  // Eigen 3.4's SparseMatrix has no move assignment: the matrix is swapped in, not copied.
  AssembledProblem assembled = assembler_->assemble_system(deadline);
  SparseMatrix a;
  a.swap(assembled.qp.A);
  problem_ = std::move(assembled);
  problem_.qp.A.swap(a);
}

template <int dim>
int Discretization<dim>::coarsest_solver_level(double max_turn) const {
  if constexpr (dim == 3) {
    return 0;
  } else {
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
}

template <int dim>
SparseMatrix Discretization<dim>::free_transfer(int coarse, int fine) const {
  SparseMatrix p;
  for (int j = coarse + 1; j <= fine; ++j) {
    const FoslsSpace<dim>& below = *spaces_[j - 1];
    const FoslsSpace<dim>& above = *spaces_[j];
    SparseMatrix step = free_prolongation<dim>(
        below, above, meshes_.maps[j],
        cartesian_prolongation<dim>(below.mesh(), above.mesh(), meshes_.maps[j]));
    if (j == coarse + 1)
      p = std::move(step);
    else
      p = SparseMatrix(step * p);
  }
  return p;
}

template <int dim>
LevelHierarchy Discretization<dim>::build_level_hierarchy(double max_share) const {
  std::vector<long long> unknowns;
  for (const auto& space : spaces_) unknowns.push_back(space->num_free());
  const auto on_contact = [&](int j, int v) { return spaces_[j]->is_contact_vertex(v); };
  const SolverLevels<dim> kept =
      skip_close_levels<dim>(meshes_, unknowns, on_contact, coarsest_solver_level(), max_share);
  LevelHierarchy h;
  h.levels.resize(kept.mesh_levels.size());
  for (std::size_t k = 0; k < kept.mesh_levels.size(); ++k) {
    const FoslsSpace<dim>& fine = *spaces_[kept.mesh_levels[k]];
    const SimplexRefinementMaps<dim>& maps = kept.maps[k];
    Level& level = h.levels[k];
    level.num_dofs = fine.num_free();
    // Local smoothing (Chen, Nochetto and Xu's multilevel methods on graded bisection grids):
    // an intermediate level smooths where it differs from the level below, so that one cycle
    // costs O(N) of the finest level however many bisection levels there are. A uniform
    // level is smoothed everywhere, the finest level always.
    const bool everywhere = k == 0 || k + 1 == kept.mesh_levels.size();
    level.patches = vertex_patches(
        fine, &level.patch_split,
        everywhere ? std::vector<char>{} : new_vertices_and_neighbours<dim>(fine.mesh(), maps));
    level.contact_strip = contact_strip(fine, kStripLayers);
    level.block_factorization = kBlockFactorization;
    if (k == 0) continue;
    const FoslsSpace<dim>& coarse = *spaces_[kept.mesh_levels[k - 1]];
    level.prolongation = free_transfer(kept.mesh_levels[k - 1], kept.mesh_levels[k]);
    level.links = contact_links<dim>(coarse, fine, maps, level.prolongation);
  }
  return h;
}

template class Discretization<2>;
template class Discretization<3>;

}  // namespace fosls
