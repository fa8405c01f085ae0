#include "mesh/bisection.hpp"

#include <stdexcept>
#include <string>

namespace fosls {

BisectionState longest_edge_state(const Mesh& mesh, int generation) {
  BisectionState s;
  s.newest.resize(mesh.num_triangles());
  s.generation.assign(mesh.num_triangles(), generation);
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    int best = 0;
    for (int k = 1; k < 3; ++k) {
      const double lk = mesh.edge_length(mesh.triangle_edge(t, k));
      const double lb = mesh.edge_length(mesh.triangle_edge(t, best));
      // A strict order on edges (length, then index): the neighbour across an edge that is
      // not its refinement edge has a longer one, so the closure cannot cycle.
      if (lk > lb || (lk == lb && mesh.triangle_edge(t, k) > mesh.triangle_edge(t, best))) best = k;
    }
    s.newest[t] = static_cast<signed char>(best);
  }
  return s;
}

namespace {

/// Marks the refinement edges of the marked triangles and closes the set: every triangle with
/// a marked edge gets its refinement edge marked. Each edge is marked once, so O(N).
std::vector<char> closed_edge_marks(const Mesh& mesh, const BisectionState& state,
                                    const std::vector<int>& marked) {
  std::vector<char> edge_marked(mesh.num_edges(), 0);
  std::vector<int> work;
  auto mark = [&](int e) {
    if (!edge_marked[e]) edge_marked[e] = 1, work.push_back(e);
  };
  for (int t : marked) mark(mesh.triangle_edge(t, state.newest[t]));
  while (!work.empty()) {
    const int e = work.back();
    work.pop_back();
    for (int t : mesh.edge_triangles(e))
      if (t >= 0) mark(mesh.triangle_edge(t, state.newest[t]));
  }
  return edge_marked;
}

}  // namespace

namespace {

void check_input(const Mesh& mesh, const BisectionState& state, const std::vector<int>& marked) {
  const int nt = mesh.num_triangles();
  if (static_cast<int>(state.newest.size()) != nt ||
      static_cast<int>(state.generation.size()) != nt)
    throw std::invalid_argument("bisection: the state does not belong to this mesh");
  for (int t : marked)
    if (t < 0 || t >= nt)
      throw std::invalid_argument("bisection: triangle " + std::to_string(t) + " does not exist");
}

/// The new vertices, the midpoints of the marked edges (on the curve where the edge is curved),
/// appended to `vertices` and to maps.midpoint_edge; returns each edge's midpoint vertex (−1:
/// not marked).
std::vector<int> add_midpoints(const Mesh& mesh, const std::vector<char>& edge_marked,
                               std::vector<Point>& vertices, RefinementMaps& maps) {
  std::vector<int> midpoint(mesh.num_edges(), -1);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!edge_marked[e]) continue;
    Point m = mesh.edge_midpoint(e);
    if (const int c = mesh.edge_curve(e); c >= 0) m = mesh.curves()[c].project(m);
    midpoint[e] = static_cast<int>(vertices.size());
    vertices.push_back(m);
    maps.midpoint_edge.push_back(e);
  }
  return midpoint;
}

/// The children of every triangle (itself when its refinement edge is not marked; two or three
/// when it is), newest vertex first for every child; their state and parents into `out`.
std::vector<std::array<int, 3>> bisect_triangles(const Mesh& mesh, const BisectionState& state,
                                                 const std::vector<char>& edge_marked,
                                                 const std::vector<int>& midpoint, Bisection& out) {
  const int nt = mesh.num_triangles();
  RefinementMaps& maps = out.maps;
  std::vector<std::array<int, 3>> triangles;
  BisectionState& fine_state = out.state;
  triangles.reserve(nt + 3 * maps.midpoint_edge.size());
  auto emit = [&](std::array<int, 3> tri, int newest, int generation, int parent) {
    triangles.push_back(tri);
    fine_state.newest.push_back(static_cast<signed char>(newest));
    fine_state.generation.push_back(generation);
    maps.triangle_parent.push_back(parent);
  };
  for (int t = 0; t < nt; ++t) {
    const int k = state.newest[t];
    const int g = state.generation[t];
    const auto& tri = mesh.triangle(t);
    const int e0 = mesh.triangle_edge(t, k);  // refinement edge (p1, p2)
    if (!edge_marked[e0]) {
      emit(tri, k, g, t);
      continue;
    }
    const int p0 = tri[k], p1 = tri[(k + 1) % 3], p2 = tri[(k + 2) % 3];
    const int e1 = mesh.triangle_edge(t, (k + 1) % 3);  // (p2, p0): refinement edge of right
    const int e2 = mesh.triangle_edge(t, (k + 2) % 3);  // (p0, p1): refinement edge of left
    const int m = midpoint[e0];
    if (edge_marked[e2]) {
      const int m2 = midpoint[e2];
      emit({m2, m, p0}, 0, g + 2, t);
      emit({m2, p1, m}, 0, g + 2, t);
    } else {
      emit({m, p0, p1}, 0, g + 1, t);
    }
    if (edge_marked[e1]) {
      const int m1 = midpoint[e1];
      emit({m1, m, p2}, 0, g + 2, t);
      emit({m1, p0, m}, 0, g + 2, t);
    } else {
      emit({m, p2, p0}, 0, g + 1, t);
    }
  }

  return triangles;
}

/// The boundary segments of the fine mesh: each boundary edge, or its two halves.
std::vector<BoundarySegment> split_boundary(const Mesh& mesh, const std::vector<int>& midpoint) {
  const int ne = mesh.num_edges();
  std::vector<BoundarySegment> segments;
  for (int e = 0; e < ne; ++e) {
    if (!mesh.is_boundary_edge(e)) continue;
    const auto& pq = mesh.edge(e);
    const int g = mesh.edge_group(e), c = mesh.edge_curve(e);
    if (midpoint[e] < 0) {
      segments.push_back({pq[0], pq[1], g, c});
    } else {
      segments.push_back({pq[0], midpoint[e], g, c});
      segments.push_back({midpoint[e], pq[1], g, c});
    }
  }
  return segments;
}

/// Edge maps: each fine edge along a coarse edge (kept or halved) or inside its parent triangle.
void set_edge_maps(const Mesh& mesh, const Mesh& fine, RefinementMaps& maps) {
  const int nv = mesh.num_vertices(), ne = mesh.num_edges();
  const int nfe = fine.num_edges();
  maps.parent_edge.assign(nfe, -1);
  maps.parent_triangle.assign(nfe, -1);
  maps.parent_sign.assign(nfe, 0);
  std::vector<std::vector<int>> coarse_edges_at(nv);
  for (int e = 0; e < ne; ++e)
    for (int v : mesh.edge(e)) coarse_edges_at[v].push_back(e);
  auto coarse_edge_between = [&](int a, int b) {
    for (int e : coarse_edges_at[a])
      if (mesh.edge(e)[0] == b || mesh.edge(e)[1] == b) return e;
    return -1;
  };
  for (int f = 0; f < nfe; ++f) {
    const int p = fine.edge(f)[0], q = fine.edge(f)[1];
    int e = -1;
    if (p < nv && q < nv) {
      e = coarse_edge_between(p, q);  // a kept coarse edge
    } else if (p < nv || q < nv) {
      const int a = p < nv ? p : q;  // coarse end point
      const int me = maps.midpoint_edge[(p < nv ? q : p) - nv];
      if (mesh.edge(me)[0] == a || mesh.edge(me)[1] == a) e = me;  // a half of edge me
    }
    if (e >= 0) {
      const auto& ce = mesh.edge(e);
      maps.parent_edge[f] = e;
      maps.parent_sign[f] = (p == ce[0] || q == ce[1]) ? 1 : -1;
    }
  }
  for (int t = 0; t < fine.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int f = fine.triangle_edge(t, k);
      if (maps.parent_edge[f] < 0) maps.parent_triangle[f] = maps.triangle_parent[t];
    }
}

}  // namespace

Bisection refine_by_bisection(const Mesh& mesh, const BisectionState& state,
                              const std::vector<int>& marked) {
  check_input(mesh, state, marked);
  const std::vector<char> edge_marked = closed_edge_marks(mesh, state, marked);
  Bisection out;
  out.maps.num_coarse_vertices = mesh.num_vertices();
  std::vector<Point> vertices(mesh.vertices());
  const std::vector<int> midpoint = add_midpoints(mesh, edge_marked, vertices, out.maps);
  std::vector<std::array<int, 3>> triangles =
      bisect_triangles(mesh, state, edge_marked, midpoint, out);
  std::vector<BoundarySegment> segments = split_boundary(mesh, midpoint);
  const std::vector<std::array<int, 3>> requested = triangles;
  out.fine = Mesh(std::move(vertices), std::move(triangles), std::move(segments),
                  mesh.group_names(), mesh.curves());
  // The Mesh constructor reorders a clockwise triangle; only a midpoint moved onto a curve
  // past the opposite vertex can cause that, and then the newest vertex would be lost.
  for (int t = 0; t < out.fine.num_triangles(); ++t)
    if (out.fine.triangle(t) != requested[t])
      throw std::runtime_error(
          "bisection: moving a boundary midpoint onto its curve inverted a triangle; the coarse "
          "mesh is too coarse for the curvature of its boundary");
  set_edge_maps(mesh, out.fine, out.maps);
  return out;
}

void refine_finest_level(MeshHierarchy& hierarchy, BisectionState& state,
                         const std::vector<int>& marked) {
  Bisection step = refine_by_bisection(hierarchy.finest(), state, marked);
  hierarchy.meshes.push_back(std::move(step.fine));
  hierarchy.maps.push_back(std::move(step.maps));
  state = std::move(step.state);
}

}  // namespace fosls
