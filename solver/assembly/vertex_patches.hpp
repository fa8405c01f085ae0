#pragma once
// The vertex patches of a level (docs/method.md §4.1), for every space: the order of the
// two-thread sweep (patch_blocks.hpp), the selection of local smoothing, and the star of DOFs
// each space puts in a vertex's patch.

#include <array>
#include <functional>
#include <vector>

#include "fem/fosls_space.hpp"

namespace fosls {

/// The patches of the vertices of `mesh` in two_vertex_blocks' order: two blocks a smoother may
/// sweep at the same time, then the separator; `split`, when given, receives the ends of the
/// two blocks. `star(v, patch)` appends vertex v's free DOFs; an empty patch is left out. Only
/// the vertices with `selected[v]` set when `selected` is not empty.
template <int dim>
std::vector<std::vector<int>> ordered_patches(
    const SimplexMesh<dim>& mesh, const std::function<void(int, std::vector<int>&)>& star,
    std::array<int, 2>* split = nullptr, const std::vector<char>& selected = {});

/// Vertex patches of a P1–RT0 space in its free numbering: the vertex's u DOFs and every σ DOF
/// of the facets through it (the Arnold–Falk–Winther star), in ordered_patches' order.
template <int dim>
std::vector<std::vector<int>> vertex_patches(const FoslsSpace<dim>& space,
                                             std::array<int, 2>* split = nullptr,
                                             const std::vector<char>& selected = {});

/// The vertices of a refined mesh that local smoothing visits: the new ones (midpoints) and
/// their neighbours. Under uniform refinement that is every vertex; under a bisection step,
/// the refined region and one layer around it.
template <int dim>
std::vector<char> new_vertices_and_neighbours(const SimplexMesh<dim>& fine,
                                              const SimplexRefinementMaps<dim>& maps);

}  // namespace fosls
