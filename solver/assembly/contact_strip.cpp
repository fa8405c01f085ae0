#include "assembly/contact_strip.hpp"

#include <algorithm>

#include "fem/fosls_space.hpp"
#include "fem/p2_rt1_space.hpp"

namespace fosls {

template <class Space>
std::vector<int> contact_strip(const Space& space, int layers) {
  const auto& mesh = space.mesh();
  std::vector<char> near(mesh.num_vertices(), 0);
  for (int f = 0; f < mesh.num_facets(); ++f)
    if (space.is_contact_facet(f))
      for (int v : mesh.facet(f)) near[v] = 1;
  auto touches = [&](int t) {
    for (int v : mesh.cell(t))
      if (near[v]) return true;
    return false;
  };
  for (int layer = 1; layer < layers; ++layer) {
    std::vector<char> next = near;
    for (int t = 0; t < mesh.num_cells(); ++t)
      if (touches(t))
        for (int v : mesh.cell(t)) next[v] = 1;
    near = std::move(next);
  }
  std::vector<char> taken(space.num_free(), 0);
  std::vector<int> strip;
  for (int t = 0; t < mesh.num_cells(); ++t)
    if (touches(t))
      for (int dof : space.cell_dofs(t))
        if (const int f = space.free_index(dof); f >= 0 && !taken[f])
          taken[f] = 1, strip.push_back(f);
  std::sort(strip.begin(), strip.end());
  return strip;
}

template std::vector<int> contact_strip<FoslsSpace<2>>(const FoslsSpace<2>&, int);
template std::vector<int> contact_strip<FoslsSpace<3>>(const FoslsSpace<3>&, int);
template std::vector<int> contact_strip<P2Rt1Space>(const P2Rt1Space&, int);

}  // namespace fosls
