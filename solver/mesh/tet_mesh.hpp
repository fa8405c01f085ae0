#pragma once
// Tetrahedral mesh with named boundary groups and the face topology that P1 and RT0 need in
// three dimensions (docs/method.md §11): the 3D counterpart of mesh.hpp.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "mesh/group_name_index.hpp"

namespace fosls {

using Point3 = Eigen::Vector3d;

/// Conventions: face k of a tetrahedron is opposite its vertex k; every face carries a unit
/// normal n_f, for an interior face (p, q, r sorted) along (q − p) × (r − p), for a boundary
/// face the outward normal of the body. The vertex order of a tetrahedron is kept as given
/// (refinement relies on it), so its orientation may be either.
/// A boundary face as a mesh source gives it: its vertices (any order) and its group.
struct BoundaryFace {
  std::array<int, 3> vertices;
  int group = -1;
};

/// A boundary group that lies on a sphere: refinement puts the midpoints of its faces' edges on
/// it (the 3D counterpart of mesh.hpp's BoundaryCurve). radius 0: the group is flat or unknown.
struct SphereSurface {
  Point3 center = Point3::Zero();
  double radius = 0.0;
  bool curved() const { return radius > 0; }
  Point3 project(const Point3& p) const { return center + radius * (p - center).normalized(); }
};

class TetMesh {
 public:
  TetMesh() = default;
  /// Builds faces and their neighbours; boundary faces not in `boundary` have no group.
  /// Throws std::invalid_argument when a face is shared by more than two tetrahedra or a
  /// tetrahedron is degenerate.
  TetMesh(std::vector<Point3> vertices, std::vector<std::array<int, 4>> tets,
          const std::vector<BoundaryFace>& boundary, std::vector<std::string> group_names,
          std::vector<SphereSurface> group_surfaces = {});

  int num_vertices() const { return static_cast<int>(vertices_.size()); }
  int num_tets() const { return static_cast<int>(tets_.size()); }
  int num_faces() const { return static_cast<int>(faces_.size()); }
  const Point3& vertex(int v) const { return vertices_[v]; }
  /// The length of the bounding box's diagonal: the body's size.
  double diameter() const;
  const std::array<int, 4>& tet(int t) const { return tets_[t]; }
  /// Face k (opposite vertex k) of tetrahedron t.
  int tet_face(int t, int k) const { return tet_faces_[t][k]; }
  /// Sorted vertices of face f.
  const std::array<int, 3>& face(int f) const { return faces_[f]; }
  const Point3& face_normal(int f) const { return face_normals_[f]; }
  double face_area(int f) const { return face_areas_[f]; }
  Point3 face_centroid(int f) const;
  double tet_volume(int t) const;
  /// Tetrahedra on either side of face f (second −1 on the boundary).
  const std::array<int, 2>& face_tets(int f) const { return face_tets_[f]; }
  /// Boundary group of face f, −1 for interior faces and ungrouped boundary faces.
  int face_group(int f) const { return face_group_[f]; }
  bool is_boundary_face(int f) const { return face_tets_[f][1] < 0; }
  const std::vector<std::string>& group_names() const { return group_names_; }
  /// Index of a group by name, −1 when absent (O(log G): group_name_index.hpp).
  int group_index(const std::string& name) const;
  /// The sphere group g lies on (not curved() for flat groups).
  SphereSurface group_surface(int g) const {
    return g >= 0 && g < static_cast<int>(group_surfaces_.size()) ? group_surfaces_[g]
                                                                  : SphereSurface{};
  }
  const std::vector<SphereSurface>& group_surfaces() const { return group_surfaces_; }
  /// Faces through each vertex (the vertex patches).
  std::vector<std::vector<int>> vertex_faces() const;
  const std::vector<Point3>& vertices() const { return vertices_; }

  // The vocabulary Mesh shares (mesh/simplex_mesh.hpp): a cell is a tetrahedron, a facet a
  // face, a facet's measure its area.
  static constexpr int kDimension = 3;
  int num_cells() const { return num_tets(); }
  const std::array<int, 4>& cell(int t) const { return tets_[t]; }
  /// Facet k of cell t: the face opposite its vertex k.
  int cell_facet(int t, int k) const { return tet_faces_[t][k]; }
  /// +1 when the global normal of facet k of cell t points out of the cell, else −1 (computed:
  /// stored, it would cost four bytes per tetrahedron for what one dot product gives).
  int cell_facet_sign(int t, int k) const;
  double cell_measure(int t) const { return tet_volume(t); }
  int num_facets() const { return num_faces(); }
  const std::array<int, 3>& facet(int f) const { return faces_[f]; }
  const Point3& facet_normal(int f) const { return face_normals_[f]; }
  double facet_measure(int f) const { return face_areas_[f]; }
  Point3 facet_centroid(int f) const { return face_centroid(f); }
  int facet_group(int f) const { return face_group_[f]; }
  const std::array<int, 2>& facet_cells(int f) const { return face_tets_[f]; }
  bool is_boundary_facet(int f) const { return is_boundary_face(f); }
  std::vector<std::vector<int>> vertex_facets() const { return vertex_faces(); }

 private:
  std::vector<Point3> vertices_;
  std::vector<std::array<int, 4>> tets_;
  std::vector<std::array<int, 4>> tet_faces_;
  std::vector<std::array<int, 3>> faces_;
  std::vector<Point3> face_normals_;
  std::vector<double> face_areas_;
  std::vector<std::array<int, 2>> face_tets_;
  std::vector<int> face_group_;
  std::vector<std::string> group_names_;
  GroupNameIndex group_index_;
  std::vector<SphereSurface> group_surfaces_;
};

/// The sorted vertex triple of a face as one key (21 bits per vertex).
long long face_key(std::array<int, 3> v);

}  // namespace fosls
