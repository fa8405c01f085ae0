#include "post/contact_output.hpp"

#include <algorithm>
#include <map>

namespace fosls {

namespace {
/// Contact edges in chain order: each chain starts at an end vertex (used by one contact edge).
std::vector<int> chain_order(const FoslsSpace& space) {
  const Mesh& mesh = space.mesh();
  std::map<int, std::vector<int>> at_vertex;
  std::vector<int> edges;
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (space.is_contact_edge(e)) {
      edges.push_back(e);
      for (int v : mesh.edge(e)) at_vertex[v].push_back(e);
    }
  std::vector<char> used(mesh.num_edges(), 0);
  std::vector<int> order;
  auto walk = [&](int e, int from) {
    while (e >= 0 && !used[e]) {
      used[e] = 1;
      order.push_back(e);
      int to = mesh.edge(e)[0] == from ? mesh.edge(e)[1] : mesh.edge(e)[0];
      int next = -1;
      for (int f : at_vertex[to])
        if (!used[f]) next = f;
      from = to;
      e = next;
    }
  };
  // Start chains at ends (vertices of one contact edge), leftmost first; then closed loops.
  std::vector<std::pair<double, int>> ends;
  for (auto& [v, es] : at_vertex)
    if (es.size() == 1) ends.push_back({mesh.vertex(v).x(), v});
  std::sort(ends.begin(), ends.end());
  for (auto [x, v] : ends)
    if (!used[at_vertex[v][0]]) walk(at_vertex[v][0], v);
  for (int e : edges)
    if (!used[e]) walk(e, mesh.edge(e)[0]);
  return order;
}
}  // namespace

ContactResult contact_output(const FoslsAssembler& assembler, const AssembledProblem& problem,
                             const Vector& x_full) {
  const FoslsSpace& space = assembler.space();
  const Mesh& mesh = space.mesh();
  ContactResult out;
  double s = 0.0;
  for (int e : chain_order(space)) {
    ContactEdgeResult r;
    r.edge = e;
    const Point m = mesh.edge_midpoint(e);
    r.x = m.x(), r.y = m.y();
    const double len = mesh.edge_length(e);
    r.s = s + 0.5 * len;
    s += len;
    const double sn = x_full[space.sigma_dof(e, 0)] * problem.stress_scale;  // ∫_e σ_nn ds
    r.pressure = 0.0 - sn / len;                                             // +0.0 where S_n = 0
    const Point ne = mesh.edge_normal(e);
    r.gap = 0.0 - assembler.edge_mean_penetration(x_full, e);  // +0.0, not −0.0, where closed
    r.active = r.pressure > 0.0;
    // σn = σ_nn n on a frictionless contact edge.
    out.force_x += sn * ne.x();
    out.force_y += sn * ne.y();
    out.edges.push_back(r);
  }
  return out;
}

}  // namespace fosls
