#pragma once
// Triangle mesh with named boundary groups and the edge topology that P1 and RT0 need.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "mesh/group_name_index.hpp"

namespace fosls {

using Point = Eigen::Vector2d;

/// A curved piece of the boundary: a circular arc with centre and radius. Midpoints created
/// by refinement on a boundary edge that lies on a curve are moved onto it.
struct BoundaryCurve {
  Point center = Point::Zero();
  double radius = 0.0;
  /// Closest point of the circle to p.
  Point project(const Point& p) const;
};

/// A boundary edge as given by a mesh source: its two vertices, the boundary group it belongs
/// to and the curve it lies on (-1 for a straight piece).
struct BoundarySegment {
  int v0 = -1;
  int v1 = -1;
  int group = -1;
  int curve = -1;
};

/// Unstructured triangle mesh.
///
/// Conventions (docs/method.md §3):
/// - triangles are counter-clockwise; edge k of a triangle is opposite its vertex k;
/// - every edge (p, q) carries the unit normal n_e = R(q − p)/|q − p| with R the clockwise
///   rotation by 90°; interior edges have p < q, boundary edges are oriented so that n_e is
///   the outward normal of the body.
class Mesh {
 public:
  Mesh() = default;
  /// Builds the topology. Throws std::invalid_argument with a readable reason when the input
  /// is not a conforming triangulation whose every boundary edge is in exactly one segment.
  Mesh(std::vector<Point> vertices, std::vector<std::array<int, 3>> triangles,
       std::vector<BoundarySegment> segments, std::vector<std::string> group_names,
       std::vector<BoundaryCurve> curves = {});

  int num_vertices() const { return static_cast<int>(vertices_.size()); }
  int num_triangles() const { return static_cast<int>(triangles_.size()); }
  int num_edges() const { return static_cast<int>(edges_.size()); }

  const Point& vertex(int v) const { return vertices_[v]; }
  const std::vector<Point>& vertices() const { return vertices_; }
  const std::array<int, 3>& triangle(int t) const { return triangles_[t]; }
  /// Global edge index of edge k (opposite vertex k) of triangle t.
  int triangle_edge(int t, int k) const { return triangle_edges_[t][k]; }
  /// +1 when the global normal of edge k of triangle t is the triangle's outward normal.
  int triangle_edge_sign(int t, int k) const { return triangle_edge_signs_[t][k]; }
  /// Oriented end points (p, q) of edge e.
  const std::array<int, 2>& edge(int e) const { return edges_[e]; }
  /// Unit normal of edge e with its global orientation.
  Point edge_normal(int e) const;
  double edge_length(int e) const;
  Point edge_midpoint(int e) const;
  double triangle_area(int t) const;

  /// Boundary group of edge e, -1 for interior edges.
  int edge_group(int e) const { return edge_group_[e]; }
  /// Curve that boundary edge e lies on, -1 when straight or interior.
  int edge_curve(int e) const { return edge_curve_[e]; }
  bool is_boundary_edge(int e) const { return edge_group_[e] >= 0; }
  /// Triangles adjacent to edge e (second is -1 on the boundary).
  const std::array<int, 2>& edge_triangles(int e) const { return edge_triangles_[e]; }

  const std::vector<std::string>& group_names() const { return group_names_; }
  /// Index of a group by name, -1 when absent (O(log G): group_name_index.hpp).
  int group_index(const std::string& name) const;
  const std::vector<BoundaryCurve>& curves() const { return curves_; }

  /// Edges incident to each vertex (vertex patches of the smoother).
  std::vector<std::vector<int>> vertex_edges() const;
  /// Smallest and largest edge length.
  std::pair<double, double> edge_length_range() const;
  /// The length of the bounding box's diagonal: the body's size.
  double diameter() const;

  // The vocabulary TetMesh shares (mesh/simplex_mesh.hpp), so that the layers written once for
  // both dimensions as `template <int dim>` see one interface: a cell is a triangle, a facet
  // an edge, a facet's measure its length.
  static constexpr int kDimension = 2;
  int num_cells() const { return num_triangles(); }
  const std::array<int, 3>& cell(int t) const { return triangles_[t]; }
  /// Facet k of cell t: the edge opposite its vertex k.
  int cell_facet(int t, int k) const { return triangle_edges_[t][k]; }
  /// +1 when the global normal of facet k of cell t is the cell's outward normal, else −1.
  int cell_facet_sign(int t, int k) const { return triangle_edge_signs_[t][k]; }
  double cell_measure(int t) const { return triangle_area(t); }
  int num_facets() const { return num_edges(); }
  const std::array<int, 2>& facet(int f) const { return edges_[f]; }
  Point facet_normal(int f) const { return edge_normal(f); }
  double facet_measure(int f) const { return edge_length(f); }
  Point facet_centroid(int f) const { return edge_midpoint(f); }
  int facet_group(int f) const { return edge_group_[f]; }
  const std::array<int, 2>& facet_cells(int f) const { return edge_triangles_[f]; }
  bool is_boundary_facet(int f) const { return edge_triangles_[f][1] < 0; }
  std::vector<std::vector<int>> vertex_facets() const { return vertex_edges(); }

 private:
  void build_topology(const std::vector<BoundarySegment>& segments);

  std::vector<Point> vertices_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<std::array<int, 3>> triangle_edges_;
  std::vector<std::array<signed char, 3>> triangle_edge_signs_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<std::array<int, 2>> edge_triangles_;
  std::vector<int> edge_group_;
  std::vector<int> edge_curve_;
  std::vector<std::string> group_names_;
  GroupNameIndex group_index_;
  std::vector<BoundaryCurve> curves_;
};

}  // namespace fosls
