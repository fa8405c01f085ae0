#include "mesh/tet_refinement.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace fosls {

namespace {

/// The fine vertex of each coarse edge's midpoint, made on first use.
class Midpoints {
 public:
  Midpoints(const TetMesh& coarse, std::vector<Point3>& vertices, TetRefinementMaps& maps)
      : coarse_(coarse), vertices_(vertices), maps_(maps) {}
  int operator()(int a, int b) {
    const long long key = (static_cast<long long>(std::min(a, b)) << 32) | std::max(a, b);
    const auto [it, added] = index_.emplace(key, static_cast<int>(vertices_.size()));
    if (added) {
      vertices_.push_back(0.5 * (coarse_.vertex(a) + coarse_.vertex(b)));
      maps_.midpoint_ends.push_back({std::min(a, b), std::max(a, b)});
    }
    return it->second;
  }

 private:
  const TetMesh& coarse_;
  std::vector<Point3>& vertices_;
  TetRefinementMaps& maps_;
  std::unordered_map<long long, int> index_;
};

/// The coarse vertices a fine vertex lies between (itself, or its edge's ends).
std::vector<int> carriers(const TetRefinementMaps& maps, int v) {
  if (v < maps.num_coarse_vertices) return {v};
  const auto& e = maps.midpoint_ends[v - maps.num_coarse_vertices];
  return {e[0], e[1]};
}

/// The area of a fine face as a fraction of the coarse face `parent` it lies in: the determinant
/// of its vertices' barycentric coordinates in the parent, whose entries 0, ½ and 1 make it exact.
double face_share(const TetRefinementMaps& maps, const std::array<int, 3>& parent,
                  const std::array<int, 3>& face) {
  Eigen::Matrix3d lambda = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const std::vector<int> c = carriers(maps, face[i]);
    for (int v : c)
      lambda(i, std::find(parent.begin(), parent.end(), v) - parent.begin()) += 1.0 / c.size();
  }
  return std::abs(lambda.determinant());
}

}  // namespace

void map_fine_faces(const TetMesh& coarse, const TetMesh& fine, TetRefinementMaps& maps) {
  std::unordered_map<long long, int> coarse_face;
  for (int f = 0; f < coarse.num_faces(); ++f) coarse_face.emplace(face_key(coarse.face(f)), f);
  maps.parent_face.assign(fine.num_faces(), -1);
  maps.parent_face_share.assign(fine.num_faces(), 0.0);
  maps.parent_tet_of_face.assign(fine.num_faces(), -1);
  for (int f = 0; f < fine.num_faces(); ++f) {
    std::vector<int> all;
    for (int v : fine.face(f))
      for (int c : carriers(maps, v)) all.push_back(c);
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (all.size() == 3)
      if (const auto it = coarse_face.find(face_key({all[0], all[1], all[2]}));
          it != coarse_face.end()) {
        maps.parent_face[f] = it->second;
        maps.parent_face_share[f] = face_share(maps, coarse.face(it->second), fine.face(f));
        continue;
      }
    maps.parent_tet_of_face[f] = maps.tet_parent[fine.face_tets(f)[0]];
  }
}

TetRefinement refine_tets_uniformly(const TetMesh& coarse) {
  TetRefinement out;
  TetRefinementMaps& maps = out.maps;
  maps.num_coarse_vertices = coarse.num_vertices();
  std::vector<Point3> vertices;
  for (int v = 0; v < coarse.num_vertices(); ++v) vertices.push_back(coarse.vertex(v));
  Midpoints mid(coarse, vertices, maps);
  std::vector<std::array<int, 4>> tets;
  tets.reserve(8 * coarse.num_tets());
  for (int t = 0; t < coarse.num_tets(); ++t) {
    const auto& x = coarse.tet(t);
    const int m01 = mid(x[0], x[1]), m02 = mid(x[0], x[2]), m03 = mid(x[0], x[3]);
    const int m12 = mid(x[1], x[2]), m13 = mid(x[1], x[3]), m23 = mid(x[2], x[3]);
    for (const std::array<int, 4>& c : {std::array<int, 4>{x[0], m01, m02, m03},
                                        {m01, x[1], m12, m13},
                                        {m02, m12, x[2], m23},
                                        {m03, m13, m23, x[3]},
                                        {m01, m02, m03, m13},
                                        {m01, m02, m12, m13},
                                        {m02, m03, m13, m23},
                                        {m02, m12, m13, m23}}) {
      tets.push_back(c);
      maps.tet_parent.push_back(t);
    }
  }
  std::vector<BoundaryFace> boundary;
  for (int f = 0; f < coarse.num_faces(); ++f) {
    if (!coarse.is_boundary_face(f) || coarse.face_group(f) < 0) continue;
    const auto& v = coarse.face(f);
    const int ab = mid(v[0], v[1]), ac = mid(v[0], v[2]), bc = mid(v[1], v[2]);
    const int g = coarse.face_group(f);
    for (const std::array<int, 3>& q :
         {std::array<int, 3>{v[0], ab, ac}, {v[1], ab, bc}, {v[2], ac, bc}, {ab, bc, ac}})
      boundary.push_back({q, g});
    // On a sphere the new vertices go onto it, as 2D's midpoints on arcs: the fine surface
    // approximates the sphere to O(h²) on every level, not just the coarse mesh's facets.
    if (const SphereSurface s = coarse.group_surface(g); s.curved())
      for (int m : {ab, ac, bc}) vertices[m] = s.project(vertices[m]);
  }
  out.fine = TetMesh(std::move(vertices), std::move(tets), boundary, coarse.group_names(),
                     coarse.group_surfaces());
  map_fine_faces(coarse, out.fine, maps);
  return out;
}

TetHierarchy build_tet_hierarchy(TetMesh coarse, int refinements) {
  return refine_repeatedly<TetMesh, TetRefinementMaps>(std::move(coarse), refinements,
                                                       refine_tets_uniformly);
}

void append_kuhn_cube(const std::array<int, 3>& start, const std::array<int, 3>& step,
                      const std::function<int(int, int, int)>& id,
                      std::vector<std::array<int, 4>>& tets) {
  const std::array<std::array<int, 3>, 6> paths = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (const auto& path : paths) {
    std::array<int, 3> c = start;
    std::array<int, 4> t;
    t[0] = id(c[0], c[1], c[2]);
    for (int s = 0; s < 3; ++s) {
      c[path[s]] += step[path[s]];
      t[s + 1] = id(c[0], c[1], c[2]);
    }
    tets.push_back(t);
  }
}

TetMesh make_box(const std::array<int, 3>& cells, const Point3& lengths) {
  const int nx = cells[0], ny = cells[1], nz = cells[2];
  auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  std::vector<Point3> vertices;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        vertices.emplace_back(lengths.x() * i / nx, lengths.y() * j / ny, lengths.z() * k / nz);
  std::vector<std::array<int, 4>> tets;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) append_kuhn_cube({i, j, k}, {1, 1, 1}, id, tets);
  const std::vector<std::string> names = {"left", "right", "front", "back", "bottom", "top"};
  const TetMesh plain(vertices, tets, {}, names);
  std::vector<BoundaryFace> boundary;
  for (int f = 0; f < plain.num_faces(); ++f) {
    if (!plain.is_boundary_face(f)) continue;
    const Point3 n = plain.face_normal(f);
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    boundary.push_back({plain.face(f), 2 * axis + (n[axis] > 0 ? 1 : 0)});
  }
  return TetMesh(std::move(vertices), std::move(tets), boundary, names);
}

}  // namespace fosls
