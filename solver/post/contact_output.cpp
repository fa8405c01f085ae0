#include "post/contact_output.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "post/contact_force.hpp"

namespace fosls {

namespace {
/// A contact edge and its vertices in the order the chain walks them.
struct ChainEdge {
  int edge;
  std::array<int, 2> ends;  ///< entered from ends[0], left at ends[1]
};

/// Contact edges in chain order: each chain starts at an end vertex (used by one contact edge).
std::vector<ChainEdge> chain_order(const FoslsSpace<2>& space) {
  const Mesh& mesh = space.mesh();
  std::map<int, std::vector<int>> at_vertex;
  std::vector<int> edges;
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (space.is_contact_edge(e)) {
      edges.push_back(e);
      for (int v : mesh.edge(e)) at_vertex[v].push_back(e);
    }
  std::vector<char> used(mesh.num_edges(), 0);
  std::vector<ChainEdge> order;
  auto walk = [&](int e, int from) {
    while (e >= 0 && !used[e]) {
      used[e] = 1;
      const int to = mesh.edge(e)[0] == from ? mesh.edge(e)[1] : mesh.edge(e)[0];
      order.push_back({e, {from, to}});
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

/// Shear, slip and whether |σ_nt| is at the bound of contact edge r.edge; returns the largest
/// |slip of the step| of its vertices, or −1 on a frictionless edge.
double set_friction_values(const FoslsAssembler<2>& assembler, const AssembledProblem& problem,
                           const Vector& x_full, double largest_bound, ContactEdgeResult& r) {
  const FoslsSpace<2>& space = assembler.space();
  const int e = r.edge;
  double vertex_slip = 0.0;
  for (int k = 0; k < 2; ++k) {
    const int v = r.ends[k];
    const Point t = slip_tangent(space, e, v);
    const double slip = tangential_displacement(space, x_full, v, t) -
                        reference_slip_origin(assembler.data(), v, t);
    r.slip += 0.5 * slip;
    r.end_slip[k] = slip;
    vertex_slip = std::max(vertex_slip, std::abs(slip));
  }
  const int st = space.sigma_dof(e, 1);
  if (space.role(st) != DofRole::kTangentialS) return -1.0;
  r.shear = x_full[st] * problem.stress_scale / r.length;
  const double bound = problem.qp.upper[space.free_index(st)];
  // At the bound up to the solver's tolerance, relative to the largest bound.
  r.at_bound = std::abs(x_full[st]) >= bound - 1e-6 * largest_bound;
  return vertex_slip;
}

/// The states from the slip of the step (ContactEdgeResult::State), and the count of those
/// that |σ_nt| against the bound contradicts.
void set_states(const std::vector<double>& vertex_slips, ContactResult& out) {
  double largest_slip = 0.0;
  for (std::size_t i = 0; i < out.edges.size(); ++i)
    if (out.edges[i].active) largest_slip = std::max(largest_slip, vertex_slips[i]);
  for (std::size_t i = 0; i < out.edges.size(); ++i) {
    ContactEdgeResult& r = out.edges[i];
    using State = ContactEdgeResult::State;
    if (!r.active) continue;  // kOpen
    if (vertex_slips[i] < 0.0) {
      r.state = State::kSlip;  // frictionless
      continue;
    }
    r.state = vertex_slips[i] <= kStickSlipTolerance * largest_slip ? State::kStick : State::kSlip;
    out.slipping_below_bound += r.state == State::kSlip && !r.at_bound;
    out.sticking_at_bound += r.state == State::kStick && r.at_bound;
  }
}
}  // namespace

const char* state_name(ContactEdgeResult::State state) {
  switch (state) {
    case ContactEdgeResult::State::kOpen:
      return "open";
    case ContactEdgeResult::State::kStick:
      return "stick";
    case ContactEdgeResult::State::kSlip:
      return "slip";
  }
  return "?";
}

ContactResult contact_output(const FoslsAssembler<2>& assembler, const AssembledProblem& problem,
                             const Vector& x_full) {
  const FoslsSpace<2>& space = assembler.space();
  const Mesh& mesh = space.mesh();
  ContactResult out;
  double s = 0.0;
  double largest_bound = 0.0;  // of the slip bounds s̄_e
  for (const FrictionEdge& f : problem.friction.edges)
    largest_bound = std::max(largest_bound, problem.qp.upper[f.st]);
  std::vector<double> vertex_slips;  // per edge of out.edges: set_friction_values
  out.frictional = !problem.friction.edges.empty();
  for (const auto& [e, ends] : chain_order(space)) {
    ContactEdgeResult r;
    r.edge = e;
    r.ends = ends;
    const Point m = mesh.edge_midpoint(e);
    r.x = m.x(), r.y = m.y();
    const double len = mesh.edge_length(e);
    r.length = len;
    r.s = s + 0.5 * len;
    s += len;
    const double sn = x_full[space.sigma_dof(e, 0)] * problem.stress_scale;  // ∫_e σ_nn ds
    r.pressure = facet_pressure(space, x_full, problem.stress_scale, e);
    const Point ne = mesh.edge_normal(e);
    r.gap = 0.0 - assembler.edge_mean_penetration(x_full, e);  // +0.0, not −0.0, where closed
    r.active = r.pressure > 0.0;
    // σn = σ_nn n + σ_nt t; σ_nt = 0 on a frictionless contact edge.
    out.force_x += sn * ne.x();
    out.force_y += sn * ne.y();
    vertex_slips.push_back(set_friction_values(assembler, problem, x_full, largest_bound, r));
    if (r.shear != 0.0) {
      out.force_x += r.shear * len * -ne.y();
      out.force_y += r.shear * len * ne.x();
    }
    out.edges.push_back(r);
  }
  set_states(vertex_slips, out);
  struct Adjacent {
    double pressure = 0, shear = 0;
    int edges = 0, state = 0;
    Point normal = Point::Zero();
  };
  std::map<int, Adjacent> adjacent;  // vertex of a contact edge → its contact edges
  for (const auto& r : out.edges)
    for (int v : mesh.edge(r.edge)) {
      adjacent[v].pressure += r.pressure;
      adjacent[v].shear += r.shear;
      adjacent[v].state = std::max(adjacent[v].state, static_cast<int>(r.state));
      adjacent[v].edges += 1;
      adjacent[v].normal += mesh.edge_normal(r.edge);
    }
  for (const auto& [v, a] : adjacent) {
    ContactVertexResult r;
    r.vertex = v;
    r.pressure = a.pressure / a.edges;
    r.shear = a.shear / a.edges;
    r.state = a.state;
    // U_n in the rotated coordinates of a contact vertex; at a vertex held by a Dirichlet
    // condition the displacement along the mean normal of its contact edges.
    const Point n = a.normal.normalized();
    const double un = space.is_contact_vertex(v)
                          ? x_full[space.u_dof(v, 0)]
                          : n.x() * x_full[space.u_dof(v, 0)] + n.y() * x_full[space.u_dof(v, 1)];
    r.gap = 0.0 + (problem.vertex_gap[v] - un);  // +0.0, not −0.0, where closed
    out.vertices.push_back(r);
  }
  return out;
}

ContactZone ContactResult::stick_zone() const {
  ContactZone z;
  for (const auto& e : edges) {
    if (e.state != ContactEdgeResult::State::kStick) continue;
    if (z.edges == 0) z.s_start = e.s - 0.5 * e.length;
    z.s_end = e.s + 0.5 * e.length;
    ++z.edges;
    z.length += e.length;
  }
  return z;
}

ContactZone ContactResult::zone() const {
  ContactZone z;
  for (const auto& e : edges) {
    if (!e.active) continue;
    if (z.edges == 0) z.s_start = e.s - 0.5 * e.length;
    z.s_end = e.s + 0.5 * e.length;
    ++z.edges;
    z.length += e.length;
    if (e.pressure > z.peak_pressure) {
      z.peak_pressure = e.pressure;
      z.peak_x = e.x;
      z.peak_y = e.y;
    }
  }
  return z;
}

}  // namespace fosls
