#include "assembly/solver_levels.hpp"

#include <algorithm>

#include "mesh/composed_refinement.hpp"

namespace fosls {

namespace {

/// Whether the composed maps of fine level `fine` leave a vertex on the contact boundary
/// without coarse weights (one inside a coarse tetrahedron: not seen, a guard).
template <int dim>
bool contact_vertex_without_weights(const SimplexRefinementMaps<dim>& maps, int fine,
                                    const std::function<bool(int, int)>& on_contact) {
  for (int k = 0; k < maps.num_midpoints(); ++k)
    if (!maps.composed_weights[k].known() && on_contact(fine, maps.num_coarse_vertices + k))
      return true;
  return false;
}

}  // namespace

template <int dim>
SolverLevels<dim> skip_close_levels(const SimplexHierarchy<dim>& meshes,
                                    const std::vector<long long>& unknowns,
                                    const std::function<bool(int, int)>& on_contact, int coarsest,
                                    double max_share) {
  SolverLevels<dim> kept;
  for (int fine = meshes.num_levels() - 1; fine > coarsest;) {
    int below = fine - 1;
    SimplexRefinementMaps<dim> maps = meshes.maps[fine];
    while (below > coarsest &&
           static_cast<double>(unknowns[below]) > max_share * static_cast<double>(unknowns[fine])) {
      SimplexRefinementMaps<dim> longer = compose_refinement_maps(
          meshes.meshes[below - 1], meshes.meshes[below], meshes.maps[below], maps);
      if (contact_vertex_without_weights<dim>(longer, fine, on_contact)) break;
      maps = std::move(longer);
      --below;
    }
    kept.mesh_levels.push_back(fine);
    kept.maps.push_back(std::move(maps));
    fine = below;
  }
  kept.mesh_levels.push_back(coarsest);
  kept.maps.emplace_back();
  std::reverse(kept.mesh_levels.begin(), kept.mesh_levels.end());
  std::reverse(kept.maps.begin(), kept.maps.end());
  return kept;
}

template SolverLevels<2> skip_close_levels<2>(const MeshHierarchy&, const std::vector<long long>&,
                                              const std::function<bool(int, int)>&, int, double);
template SolverLevels<3> skip_close_levels<3>(const TetHierarchy&, const std::vector<long long>&,
                                              const std::function<bool(int, int)>&, int, double);

}  // namespace fosls
