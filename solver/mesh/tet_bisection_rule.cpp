#include "mesh/tet_bisection_rule.hpp"

#include <algorithm>
#include <utility>

namespace fosls {

MarkedTet marked_tet(const std::array<int, 4>& vertices, const TetLabel& label) {
  MarkedTet t;
  for (int i = 0; i < 4; ++i) t.v[i] = vertices[label.order[i]];
  t.peak = {vertices[label.peak[0]], vertices[label.peak[1]]};
  t.flagged = label.flagged;
  return t;
}

TetLabel label_of(const MarkedTet& t) {
  auto local = [&t](int vertex) {
    return static_cast<signed char>(std::find(t.v.begin(), t.v.end(), vertex) - t.v.begin());
  };
  return {{0, 1, 2, 3}, {local(t.peak[0]), local(t.peak[1])}, t.flagged};
}

bool valid_label(const TetLabel& label) {
  std::array<signed char, 4> sorted = label.order;
  std::sort(sorted.begin(), sorted.end());
  if (sorted != std::array<signed char, 4>{0, 1, 2, 3}) return false;
  // Each peak is a vertex of its face: not the vertex the face is opposite to.
  return label.peak[0] >= 0 && label.peak[0] < 4 && label.peak[0] != label.order[0] &&
         label.peak[1] >= 0 && label.peak[1] < 4 && label.peak[1] != label.order[1];
}

namespace {

/// Child `side` (0: keeps v[0], 1: keeps v[1]) of t, cut at m. Its faces: the one opposite m is
/// t's face opposite v[1 − side], kept whole with its marking; the one opposite the kept end is
/// the new face (m, v2, v3); the other two are halves of t's faces through the refinement edge,
/// marked on their edge of t, so their peak is m.
MarkedTet child(const MarkedTet& t, int m, int side) {
  const int kept = t.v[side];
  const int inherited_peak = t.peak[1 - side];
  // The new face is marked on v2 v3 (peak m), in a flagged planar t on m and the apex, the one of
  // v2, v3 that is not the common peak: Maubach's tag-1 step, which closes the cycle of types.
  const int new_face_peak = t.planar() && t.flagged ? t.peak[0] : m;
  auto peak_of_face_without = [&](int vertex) {
    if (vertex == m) return inherited_peak;
    if (vertex == kept) return new_face_peak;
    return m;
  };
  // The refinement edge: the marked edge of the kept face (kept, v2, v3) of t.
  std::array<int, 3> kept_face = {kept, t.v[2], t.v[3]};
  std::array<int, 2> edge{};
  int n = 0;
  for (int x : kept_face)
    if (x != inherited_peak) edge[n++] = x;
  MarkedTet c;
  c.v = {edge[0], edge[1], inherited_peak, m};
  c.peak = {peak_of_face_without(c.v[0]), peak_of_face_without(c.v[1])};
  c.flagged = t.planar() && !t.flagged;
  c.depth = t.depth + 1;
  return c;
}

}  // namespace

std::array<MarkedTet, 2> bisect(const MarkedTet& t, int midpoint) {
  return {child(t, midpoint, 0), child(t, midpoint, 1)};
}

}  // namespace fosls

namespace fosls {

namespace {

/// A strict order on edges: length, then the sorted vertex pair. Lengths are computed from the
/// sorted pair, so an edge has the same rank from every tetrahedron and face around it.
bool ranks_above(const TetMesh& mesh, int a, int b, int c, int d) {
  if (a > b) std::swap(a, b);
  if (c > d) std::swap(c, d);
  const double lab = (mesh.vertex(b) - mesh.vertex(a)).squaredNorm();
  const double lcd = (mesh.vertex(d) - mesh.vertex(c)).squaredNorm();
  if (lab != lcd) return lab > lcd;
  return std::make_pair(a, b) > std::make_pair(c, d);
}

/// The local vertex of tetrahedron t's face opposite local vertex k that its top-ranked edge
/// leaves out.
signed char face_peak(const TetMesh& mesh, int t, int k) {
  const auto& x = mesh.tet(t);
  std::array<int, 3> f = {(k + 1) % 4, (k + 2) % 4, (k + 3) % 4};
  int best = 0;  // edge i of the face leaves out f[i]
  for (int i = 1; i < 3; ++i)
    if (ranks_above(mesh, x[f[(i + 1) % 3]], x[f[(i + 2) % 3]], x[f[(best + 1) % 3]],
                    x[f[(best + 2) % 3]]))
      best = i;
  return static_cast<signed char>(f[best]);
}

}  // namespace

TetBisectionState initial_tet_bisection_state(const TetMesh& mesh, int generation) {
  TetBisectionState state;
  state.generation.assign(mesh.num_tets(), generation);
  for (int t = 0; t < mesh.num_tets(); ++t) {
    const auto& x = mesh.tet(t);
    std::array<int, 2> top = {0, 1};
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (ranks_above(mesh, x[i], x[j], x[top[0]], x[top[1]])) top = {i, j};
    TetLabel label;
    int n = 2;
    label.order[0] = static_cast<signed char>(top[0]);
    label.order[1] = static_cast<signed char>(top[1]);
    for (int i = 0; i < 4; ++i)
      if (i != top[0] && i != top[1]) label.order[n++] = static_cast<signed char>(i);
    label.peak = {face_peak(mesh, t, top[0]), face_peak(mesh, t, top[1])};
    state.labels.push_back(label);
  }
  return state;
}

}  // namespace fosls
