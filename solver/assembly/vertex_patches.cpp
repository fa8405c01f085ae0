#include "assembly/vertex_patches.hpp"

#include "assembly/patch_blocks.hpp"

namespace fosls {

template <int dim>
std::vector<std::vector<int>> ordered_patches(
    const SimplexMesh<dim>& mesh, const std::function<void(int, std::vector<int>&)>& star,
    std::array<int, 2>* split, const std::vector<char>& selected) {
  const VertexBlocks blocks = two_vertex_blocks(mesh);
  std::vector<std::vector<int>> patches;
  patches.reserve(mesh.num_vertices());
  for (int k = 0; k < mesh.num_vertices(); ++k) {
    for (int b = 0; b < 2; ++b)
      if (split && k == blocks.ends[b]) (*split)[b] = static_cast<int>(patches.size());
    const int v = blocks.order[k];
    if (!selected.empty() && !selected[v]) continue;
    std::vector<int> p;
    star(v, p);
    if (!p.empty()) patches.push_back(std::move(p));
  }
  for (int b = 0; b < 2; ++b)
    if (split && blocks.ends[b] == mesh.num_vertices())
      (*split)[b] = static_cast<int>(patches.size());
  return patches;
}

template <int dim>
std::vector<std::vector<int>> vertex_patches(const FoslsSpace<dim>& space,
                                             std::array<int, 2>* split,
                                             const std::vector<char>& selected) {
  const auto vertex_facets = space.mesh().vertex_facets();
  auto star = [&](int v, std::vector<int>& p) {
    auto take = [&](int dof) {
      if (const int f = space.free_index(dof); f >= 0) p.push_back(f);
    };
    for (int c = 0; c < dim; ++c) take(space.u_dof(v, c));
    for (int f : vertex_facets[v])
      for (int i = 0; i < dim; ++i) take(space.sigma_dof(f, i));
  };
  return ordered_patches<dim>(space.mesh(), star, split, selected);
}

template <int dim>
std::vector<char> new_vertices_and_neighbours(const SimplexMesh<dim>& fine,
                                              const SimplexRefinementMaps<dim>& maps) {
  // A vertex shares an edge with a new one exactly when it shares a cell with it.
  std::vector<char> selected(fine.num_vertices(), 0);
  for (int t = 0; t < fine.num_cells(); ++t) {
    const auto& cell = fine.cell(t);
    bool refined = false;
    for (int v : cell) refined |= v >= maps.num_coarse_vertices;
    if (refined)
      for (int v : cell) selected[v] = 1;
  }
  return selected;
}

template std::vector<std::vector<int>> ordered_patches<2>(
    const Mesh&, const std::function<void(int, std::vector<int>&)>&, std::array<int, 2>*,
    const std::vector<char>&);
template std::vector<std::vector<int>> ordered_patches<3>(
    const TetMesh&, const std::function<void(int, std::vector<int>&)>&, std::array<int, 2>*,
    const std::vector<char>&);
template std::vector<std::vector<int>> vertex_patches<2>(const FoslsSpace<2>&, std::array<int, 2>*,
                                                         const std::vector<char>&);
template std::vector<std::vector<int>> vertex_patches<3>(const FoslsSpace<3>&, std::array<int, 2>*,
                                                         const std::vector<char>&);
template std::vector<char> new_vertices_and_neighbours<2>(const Mesh&, const RefinementMaps&);
template std::vector<char> new_vertices_and_neighbours<3>(const TetMesh&, const TetRefinementMaps&);

}  // namespace fosls
