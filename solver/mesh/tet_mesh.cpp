#include "mesh/tet_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace fosls {

long long face_key(std::array<int, 3> v) {
  std::sort(v.begin(), v.end());
  return (static_cast<long long>(v[0]) << 42) | (static_cast<long long>(v[1]) << 21) | v[2];
}

TetMesh::TetMesh(std::vector<Point3> vertices, std::vector<std::array<int, 4>> tets,
                 const std::vector<BoundaryFace>& boundary, std::vector<std::string> group_names,
                 std::vector<SphereSurface> group_surfaces)
    : vertices_(std::move(vertices)),
      tets_(std::move(tets)),
      group_names_(std::move(group_names)),
      group_index_(group_names_),
      group_surfaces_(std::move(group_surfaces)) {
  std::unordered_map<long long, int> index;
  index.reserve(2 * tets_.size() + 16);
  tet_faces_.resize(tets_.size());
  for (int t = 0; t < num_tets(); ++t) {
    if (!(tet_volume(t) > 0))
      throw std::invalid_argument("tetrahedron " + std::to_string(t) + " is degenerate");
    for (int k = 0; k < 4; ++k) {
      std::array<int, 3> f = {tets_[t][(k + 1) % 4], tets_[t][(k + 2) % 4], tets_[t][(k + 3) % 4]};
      std::sort(f.begin(), f.end());
      const auto [it, added] = index.emplace(face_key(f), num_faces());
      if (added) {
        faces_.push_back(f);
        face_tets_.push_back({t, -1});
      } else if (face_tets_[it->second][1] >= 0) {
        throw std::invalid_argument("a face is shared by more than two tetrahedra");
      } else {
        face_tets_[it->second][1] = t;
      }
      tet_faces_[t][k] = it->second;
    }
  }
  face_group_.assign(num_faces(), -1);
  for (const BoundaryFace& b : boundary)
    if (const auto it = index.find(face_key(b.vertices)); it != index.end())
      face_group_[it->second] = b.group;
  face_normals_.resize(num_faces());
  face_areas_.resize(num_faces());
  for (int f = 0; f < num_faces(); ++f) {
    const auto& v = faces_[f];
    const Point3 cross =
        (vertices_[v[1]] - vertices_[v[0]]).cross(vertices_[v[2]] - vertices_[v[0]]);
    face_areas_[f] = 0.5 * cross.norm();
    Point3 n = cross.normalized();
    if (face_tets_[f][1] < 0) {
      // Outward: away from the vertex of the one tetrahedron that is not on the face.
      const int t = face_tets_[f][0];
      int k = 0;
      while (tet_faces_[t][k] != f) ++k;
      if (n.dot(face_centroid(f) - vertices_[tets_[t][k]]) < 0) n = -n;
    }
    face_normals_[f] = n;
  }
}

Point3 TetMesh::face_centroid(int f) const {
  const auto& v = faces_[f];
  return (vertices_[v[0]] + vertices_[v[1]] + vertices_[v[2]]) / 3.0;
}

double TetMesh::tet_volume(int t) const {
  const auto& v = tets_[t];
  const Point3 a = vertices_[v[1]] - vertices_[v[0]], b = vertices_[v[2]] - vertices_[v[0]],
               c = vertices_[v[3]] - vertices_[v[0]];
  return std::abs(a.dot(b.cross(c))) / 6.0;
}

int TetMesh::cell_facet_sign(int t, int k) const {
  const int f = tet_faces_[t][k];
  return face_normals_[f].dot(face_centroid(f) - vertices_[tets_[t][k]]) > 0 ? 1 : -1;
}

int TetMesh::group_index(const std::string& name) const {
  return group_index_.find(group_names_, name);
}

std::vector<std::vector<int>> TetMesh::vertex_faces() const {
  std::vector<std::vector<int>> out(num_vertices());
  for (int f = 0; f < num_faces(); ++f)
    for (int v : faces_[f]) out[v].push_back(f);
  return out;
}

double TetMesh::diameter() const {
  Point3 lo = vertices_.front(), hi = vertices_.front();
  for (const Point3& x : vertices_) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  return (hi - lo).norm();
}

}  // namespace fosls
