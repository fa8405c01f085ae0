#include "mesh/tet_bisection.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "mesh/tet_bisection_rule.hpp"

namespace fosls {

namespace {

long long pair_key(int a, int b) {
  return (static_cast<long long>(std::min(a, b)) << 32) | std::max(a, b);
}

/// The six local vertex pairs of a tetrahedron.
constexpr std::array<std::array<int, 2>, 6> kTetEdges = {
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

/// The input mesh's edges, the tetrahedra around each, and which are bisected in this step. A
/// new vertex is numbered num_vertices + (its edge's index) until the step is done.
class InputEdges {
 public:
  explicit InputEdges(const TetMesh& mesh) : num_vertices_(mesh.num_vertices()) {
    for (int t = 0; t < mesh.num_tets(); ++t)
      for (const auto& [i, j] : kTetEdges) {
        const int a = mesh.tet(t)[i], b = mesh.tet(t)[j];
        const auto [it, added] = index_.emplace(pair_key(a, b), static_cast<int>(ends_.size()));
        if (added) ends_.push_back({std::min(a, b), std::max(a, b)}), tets_.emplace_back();
        tets_[it->second].push_back(t);
      }
    bisected_.assign(ends_.size(), 0);
  }
  int size() const { return static_cast<int>(ends_.size()); }
  /// The input edge between vertices a and b, −1 when they span none (a new vertex among them).
  int find(int a, int b) const {
    if (a >= num_vertices_ || b >= num_vertices_) return -1;
    const auto it = index_.find(pair_key(a, b));
    return it == index_.end() ? -1 : it->second;
  }
  bool bisected(int a, int b) const {
    const int e = find(a, b);
    return e >= 0 && bisected_[e];
  }
  bool bisected(int e) const { return bisected_[e]; }
  /// Marks edge e; false if it was marked already.
  bool bisect(int e) { return !std::exchange(bisected_[e], 1); }
  /// Unmarks edge e; false if it was not marked.
  bool unbisect(int e) { return std::exchange(bisected_[e], 0); }
  int midpoint(int a, int b) const { return num_vertices_ + find(a, b); }
  const std::array<int, 2>& ends(int e) const { return ends_[e]; }
  const std::vector<int>& tets(int e) const { return tets_[e]; }
  /// The input vertices a vertex of the step lies between: itself, or its edge's ends.
  std::vector<int> carriers(int v) const {
    if (v < num_vertices_) return {v};
    return {ends_[v - num_vertices_][0], ends_[v - num_vertices_][1]};
  }

 private:
  int num_vertices_;
  std::unordered_map<long long, int> index_;
  std::vector<std::array<int, 2>> ends_;
  std::vector<std::vector<int>> tets_;
  std::vector<char> bisected_;
};

/// The leaves of `root`'s bisection tree: it is cut while its refinement edge is a marked input
/// edge, at most kMaxBisectionsPerStep deep. `visit` returns true to stop the walk.
template <class Visit>
bool walk_leaves(const MarkedTet& root, const InputEdges& edges, Visit&& visit) {
  if (root.depth < kMaxBisectionsPerStep && edges.bisected(root.v[0], root.v[1])) {
    for (const MarkedTet& c : bisect(root, edges.midpoint(root.v[0], root.v[1])))
      if (walk_leaves(c, edges, visit)) return true;
    return false;
  }
  return visit(root);
}

/// Whether a leaf would leave a vertex hanging: one of its edges is a marked input edge.
bool holds_bisected_edge(const MarkedTet& leaf, const InputEdges& edges) {
  for (const auto& [i, j] : kTetEdges)
    if (edges.bisected(leaf.v[i], leaf.v[j])) return true;
  return false;
}

/// Marks the refinement edges of the marked tetrahedra (as deep as each is listed) and closes the
/// set: a leaf that still holds a marked edge gets its refinement edge marked. Only input edges
/// are marked; a leaf whose refinement edge is new would need a vertex off them: it is refused,
/// or with `defer` left for prune_to_conforming.
void close_marks(const TetMesh& mesh, const TetBisectionState& state,
                 const std::vector<int>& depth_wanted, bool defer, InputEdges& edges) {
  std::deque<int> work;
  std::vector<char> queued(mesh.num_tets(), 0);
  auto enqueue = [&](int t) {
    if (!queued[t]) queued[t] = 1, work.push_back(t);
  };
  for (int t = 0; t < mesh.num_tets(); ++t)
    if (depth_wanted[t] > 0) enqueue(t);
  while (!work.empty()) {
    const int t = work.front();
    work.pop_front();
    queued[t] = 0;
    walk_leaves(marked_tet(mesh.tet(t), state.labels[t]), edges, [&](const MarkedTet& leaf) {
      if (leaf.depth >= depth_wanted[t] && !holds_bisected_edge(leaf, edges)) return false;
      const int e = edges.find(leaf.v[0], leaf.v[1]);
      if ((e < 0 || leaf.depth >= kMaxBisectionsPerStep) && defer) return false;
      if (e < 0 || leaf.depth >= kMaxBisectionsPerStep)
        throw std::runtime_error(
            "tetrahedron bisection: the closure would bisect tetrahedron " + std::to_string(t) +
            " (generation " + std::to_string(state.generation[t]) + ") " +
            std::to_string(leaf.depth + 1) +
            " times in one step, at a vertex that is not the midpoint of an edge of the input "
            "mesh; split the step (refine_finest_tet_level does)");
      if (edges.bisect(e))
        for (int s : edges.tets(e)) enqueue(s);
      return true;  // t is queued again: walk its new tree afresh
    });
  }
}

/// Unmarks every marked edge that a leaf still holds (its refinement edge is new, or was
/// unmarked), until none does: the largest part of the step that is conforming with vertices at
/// input edges only. What it leaves out is done in a next step from the finer mesh.
void prune_to_conforming(const TetMesh& mesh, const TetBisectionState& state, InputEdges& edges) {
  std::deque<int> work;
  std::vector<char> queued(mesh.num_tets(), 0);
  auto enqueue = [&](int t) {
    if (!queued[t]) queued[t] = 1, work.push_back(t);
  };
  for (int e = 0; e < edges.size(); ++e)
    if (edges.bisected(e))
      for (int t : edges.tets(e)) enqueue(t);
  while (!work.empty()) {
    const int t = work.front();
    work.pop_front();
    queued[t] = 0;
    walk_leaves(marked_tet(mesh.tet(t), state.labels[t]), edges, [&](const MarkedTet& leaf) {
      bool pruned = false;
      for (const auto& [i, j] : kTetEdges)
        if (const int e = edges.find(leaf.v[i], leaf.v[j]); e >= 0 && edges.unbisect(e)) {
          pruned = true;
          for (int s : edges.tets(e)) enqueue(s);
        }
      return pruned;  // t is queued again
    });
  }
}

void check_input(const TetMesh& mesh, const TetBisectionState& state,
                 const std::vector<int>& marked, std::vector<int>& depth_wanted) {
  const int nt = mesh.num_tets();
  if (static_cast<int>(state.labels.size()) != nt ||
      static_cast<int>(state.generation.size()) != nt)
    throw std::invalid_argument("tetrahedron bisection: the state does not belong to this mesh");
  for (int t = 0; t < nt; ++t)
    if (!valid_label(state.labels[t]))
      throw std::invalid_argument("tetrahedron bisection: the label of tetrahedron " +
                                  std::to_string(t) + " is not a marking");
  depth_wanted.assign(nt, 0);
  for (int t : marked) {
    if (t < 0 || t >= nt)
      throw std::invalid_argument("tetrahedron bisection: tetrahedron " + std::to_string(t) +
                                  " does not exist");
    if (++depth_wanted[t] > kMaxBisectionsPerStep)
      throw std::invalid_argument("tetrahedron bisection: tetrahedron " + std::to_string(t) +
                                  " is marked more than " + std::to_string(kMaxBisectionsPerStep) +
                                  " times");
  }
}

/// Everything the fine mesh is made of, in the step's vertex numbers (new vertex = input vertex
/// count + edge index).
struct FineTets {
  std::vector<std::array<int, 4>> tets;
  std::vector<BoundaryFace> boundary;
};

/// The leaves' faces that lie in the input boundary faces of tetrahedron t (all their vertices
/// between the face's three), with that face's group.
void collect_boundary(const TetMesh& mesh, int t, const MarkedTet& leaf, const InputEdges& edges,
                      std::vector<BoundaryFace>& boundary) {
  for (int k = 0; k < 4; ++k) {
    const int f = mesh.tet_face(t, k);
    if (!mesh.is_boundary_face(f) || mesh.face_group(f) < 0) continue;
    const auto& coarse = mesh.face(f);
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> face{};
      bool inside = true;
      for (int i = 0, n = 0; i < 4; ++i) {
        if (i == skip) continue;
        face[n++] = leaf.v[i];
        for (int c : edges.carriers(leaf.v[i]))
          inside &= std::find(coarse.begin(), coarse.end(), c) != coarse.end();
      }
      if (inside) boundary.push_back({face, mesh.face_group(f)});
    }
  }
}

/// The fine tetrahedra, their state and parents, and the fine boundary faces.
FineTets bisect_tets(const TetMesh& mesh, const TetBisectionState& state, const InputEdges& edges,
                     TetBisection& out) {
  FineTets fine;
  for (int t = 0; t < mesh.num_tets(); ++t) {
    const MarkedTet root = marked_tet(mesh.tet(t), state.labels[t]);
    if (!edges.bisected(root.v[0], root.v[1])) {  // kept, in its own vertex order
      fine.tets.push_back(mesh.tet(t));
      out.state.labels.push_back(state.labels[t]);
      out.state.generation.push_back(state.generation[t]);
      out.maps.tet_parent.push_back(t);
      for (int k = 0; k < 4; ++k)
        if (const int f = mesh.tet_face(t, k); mesh.is_boundary_face(f) && mesh.face_group(f) >= 0)
          fine.boundary.push_back({mesh.face(f), mesh.face_group(f)});
      continue;
    }
    walk_leaves(root, edges, [&](const MarkedTet& leaf) {
      fine.tets.push_back(leaf.v);
      out.state.labels.push_back(label_of(leaf));
      out.state.generation.push_back(state.generation[t] + leaf.depth);
      out.maps.tet_parent.push_back(t);
      collect_boundary(mesh, t, leaf, edges, fine.boundary);
      return false;
    });
  }
  return fine;
}

double signed_volume(const std::vector<Point3>& x, const std::array<int, 4>& t) {
  return (x[t[1]] - x[t[0]]).dot((x[t[2]] - x[t[0]]).cross(x[t[3]] - x[t[0]]));
}

/// The fine vertices: the input ones, then the midpoints of the bisected edges in edge order (on
/// the sphere of a curved group whose face holds the edge, as red refinement puts them); the step's
/// vertex numbers in `fine` become the final ones. Throws when a moved midpoint inverts a leaf.
std::vector<Point3> place_vertices(const TetMesh& mesh, const InputEdges& edges, FineTets& fine,
                                   TetRefinementMaps& maps) {
  const int nv = mesh.num_vertices();
  std::vector<Point3> flat;
  for (int v = 0; v < nv; ++v) flat.push_back(mesh.vertex(v));
  std::vector<int> number(nv + edges.size(), -1);
  for (int v = 0; v < nv; ++v) number[v] = v;
  for (int e = 0; e < edges.size(); ++e) {
    if (!edges.bisected(e)) continue;
    const auto& ab = edges.ends(e);
    number[nv + e] = static_cast<int>(flat.size());
    flat.push_back(0.5 * (mesh.vertex(ab[0]) + mesh.vertex(ab[1])));
    maps.midpoint_ends.push_back(ab);
  }
  std::vector<Point3> placed = flat;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const SphereSurface s = mesh.group_surface(mesh.face_group(f));
    if (!mesh.is_boundary_face(f) || !s.curved()) continue;
    const auto& v = mesh.face(f);
    for (int i = 0; i < 3; ++i)
      if (const int e = edges.find(v[i], v[(i + 1) % 3]); e >= 0 && edges.bisected(e))
        placed[number[nv + e]] = s.project(flat[number[nv + e]]);
  }
  for (auto& t : fine.tets) {
    for (int& v : t) v = number[v];
    if (!(signed_volume(flat, t) * signed_volume(placed, t) > 0))
      throw std::runtime_error(
          "tetrahedron bisection: moving a midpoint onto its sphere inverted a tetrahedron; the "
          "coarse mesh is too coarse for the curvature of its boundary");
  }
  for (auto& b : fine.boundary)
    for (int& v : b.vertices) v = number[v];
  return placed;
}

}  // namespace

namespace {

/// The step (defer: the part of it) and, per fine tetrahedron, how often it is still to be
/// bisected for the marks: its parent's generation plus its marks, less its own generation.
TetBisection bisect_step(const TetMesh& mesh, const TetBisectionState& state,
                         const std::vector<int>& marked, bool defer, std::vector<int>* remaining) {
  std::vector<int> depth_wanted;
  check_input(mesh, state, marked, depth_wanted);
  InputEdges edges(mesh);
  close_marks(mesh, state, depth_wanted, defer, edges);
  if (defer) prune_to_conforming(mesh, state, edges);
  TetBisection out;
  out.maps.num_coarse_vertices = mesh.num_vertices();
  FineTets fine = bisect_tets(mesh, state, edges, out);
  std::vector<Point3> vertices = place_vertices(mesh, edges, fine, out.maps);
  out.fine = TetMesh(std::move(vertices), std::move(fine.tets), fine.boundary, mesh.group_names(),
                     mesh.group_surfaces());
  map_fine_faces(mesh, out.fine, out.maps);
  if (remaining) {
    remaining->clear();
    for (int t = 0; t < out.fine.num_tets(); ++t) {
      const int parent = out.maps.tet_parent[t];
      const int target = state.generation[parent] + depth_wanted[parent];
      for (int k = out.state.generation[t]; k < target; ++k) remaining->push_back(t);
    }
  }
  return out;
}

}  // namespace

TetBisection refine_tets_by_bisection(const TetMesh& mesh, const TetBisectionState& state,
                                      const std::vector<int>& marked) {
  return bisect_step(mesh, state, marked, false, nullptr);
}

TetBisection refine_tets_by_bisection_in_part(const TetMesh& mesh, const TetBisectionState& state,
                                              const std::vector<int>& marked,
                                              std::vector<int>& remaining) {
  return bisect_step(mesh, state, marked, true, &remaining);
}

int refine_finest_tet_level(TetHierarchy& hierarchy, TetBisectionState& state,
                            const std::vector<int>& marked) {
  std::vector<int> todo = marked, remaining;
  int levels = 0;
  do {
    TetBisection step =
        refine_tets_by_bisection_in_part(hierarchy.finest(), state, todo, remaining);
    // Each part cuts at least one edge; the whole step's closure is finite
    // (Arnold–Mukherjee–Pouly).
    if (!todo.empty() && step.fine.num_tets() == hierarchy.finest().num_tets())
      throw std::runtime_error("tetrahedron bisection: a step made no progress (internal error)");
    hierarchy.meshes.push_back(std::move(step.fine));
    hierarchy.maps.push_back(std::move(step.maps));
    state = std::move(step.state);
    todo.swap(remaining);
    ++levels;
  } while (!todo.empty());
  return levels;
}

}  // namespace fosls
