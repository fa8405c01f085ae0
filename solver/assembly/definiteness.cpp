#include "assembly/definiteness.hpp"

#include <Eigen/SparseCholesky>

namespace fosls {

bool contact_layer_is_definite(const FoslsSpace<2>& space, const BoxQp& qp) {
  const Mesh& mesh = space.mesh();
  std::vector<char> near(mesh.num_vertices(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (space.is_contact_edge(e))
      for (int v : mesh.edge(e)) near[v] = 1;
  std::vector<char> in_layer(mesh.num_triangles(), 0);
  for (int layer = 0; layer < 2; ++layer) {
    for (int t = 0; t < mesh.num_triangles(); ++t)
      for (int v : mesh.triangle(t)) in_layer[t] |= near[v];
    for (int t = 0; t < mesh.num_triangles(); ++t)
      if (in_layer[t])
        for (int v : mesh.triangle(t)) near[v] = 1;
  }
  std::vector<int> local(qp.size(), -1);
  std::vector<int> dofs;
  auto take = [&](int full) {
    int f = space.free_index(full);
    if (f >= 0 && local[f] < 0) local[f] = static_cast<int>(dofs.size()), dofs.push_back(f);
  };
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    if (!in_layer[t]) continue;
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 2; ++c) {
        take(space.u_dof(mesh.triangle(t)[k], c));
        take(space.sigma_dof(mesh.triangle_edge(t, k), c));
      }
  }
  if (dofs.empty()) return true;
  std::vector<Eigen::Triplet<double>> trip;
  for (std::size_t a = 0; a < dofs.size(); ++a)
    for (SparseMatrix::InnerIterator it(qp.A, dofs[a]); it; ++it)
      if (int b = local[it.row()]; b >= 0) trip.emplace_back(b, static_cast<int>(a), it.value());
  SparseMatrix sub(dofs.size(), dofs.size());
  sub.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(sub);
  if (ldlt.info() != Eigen::Success) return false;
  return (ldlt.vectorD().array() > 0).all();
}

}  // namespace fosls
