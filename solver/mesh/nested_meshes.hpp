#pragma once
// What refinement produces, written once for triangles and tetrahedra: one step (the fine mesh
// with its parent/child maps, and a bisection's labels), the nested meshes of a hierarchy, and a
// hierarchy by repeating a uniform rule. The meshes, maps and rules themselves stay per
// dimension (docs/architecture.md, "Three dimensions").

#include <stdexcept>
#include <utility>
#include <vector>

namespace fosls {

/// One refinement step: the fine mesh and how it relates to the coarse one.
template <class MeshT, class MapsT>
struct RefinementStep {
  MeshT fine;
  MapsT maps;
};

/// One bisection step: a refinement step and the fine mesh's bisection labels.
template <class MeshT, class MapsT, class StateT>
struct BisectionStep : RefinementStep<MeshT, MapsT> {
  StateT state;
};

/// Meshes of all levels, coarsest first, and maps[j] relating level j−1 to level j (maps[0]
/// is empty).
template <class MeshT, class MapsT>
struct NestedMeshes {
  std::vector<MeshT> meshes;
  std::vector<MapsT> maps;
  int num_levels() const { return static_cast<int>(meshes.size()); }
  const MeshT& finest() const { return meshes.back(); }
};

/// The coarse mesh and `refinements` steps of `refine` (a uniform rule: mesh → RefinementStep).
template <class MeshT, class MapsT, class Refine>
NestedMeshes<MeshT, MapsT> refine_repeatedly(MeshT coarse, int refinements, Refine refine) {
  if (refinements < 0) throw std::invalid_argument("refinements must be non-negative");
  NestedMeshes<MeshT, MapsT> h;
  h.meshes.push_back(std::move(coarse));
  h.maps.emplace_back();
  for (int r = 0; r < refinements; ++r) {
    RefinementStep<MeshT, MapsT> step = refine(h.meshes.back());
    h.meshes.push_back(std::move(step.fine));
    h.maps.push_back(std::move(step.maps));
  }
  return h;
}

}  // namespace fosls
