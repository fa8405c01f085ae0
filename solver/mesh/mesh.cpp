#include "mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fosls {

Point BoundaryCurve::project(const Point& p) const {
  Point d = p - center;
  double n = d.norm();
  if (n == 0.0) return p;
  return center + radius * d / n;
}

namespace {
double signed_area(const Point& a, const Point& b, const Point& c) {
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
}
std::uint64_t edge_key(int a, int b) {
  auto lo = static_cast<std::uint64_t>(std::min(a, b));
  auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}
}  // namespace

Mesh::Mesh(std::vector<Point> vertices, std::vector<std::array<int, 3>> triangles,
           std::vector<BoundarySegment> segments, std::vector<std::string> group_names,
           std::vector<BoundaryCurve> curves)
    : vertices_(std::move(vertices)),
      triangles_(std::move(triangles)),
      group_names_(std::move(group_names)),
      group_index_(group_names_),
      curves_(std::move(curves)) {
  if (triangles_.empty()) throw std::invalid_argument("the mesh has no triangles");
  const int nv = num_vertices();
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    auto& tri = triangles_[t];
    for (int v : tri)
      if (v < 0 || v >= nv)
        throw std::invalid_argument("triangle " + std::to_string(t) +
                                    " refers to a vertex that does not exist");
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw std::invalid_argument("triangle " + std::to_string(t) + " repeats a vertex");
    double area = signed_area(vertices_[tri[0]], vertices_[tri[1]], vertices_[tri[2]]);
    double scale = (vertices_[tri[1]] - vertices_[tri[0]]).squaredNorm() +
                   (vertices_[tri[2]] - vertices_[tri[0]]).squaredNorm();
    if (!(std::abs(area) > 1e-14 * scale))
      throw std::invalid_argument("triangle " + std::to_string(t) + " has zero area");
    if (area < 0) std::swap(tri[1], tri[2]);
  }
  for (const auto& s : segments) {
    if (s.v0 < 0 || s.v0 >= nv || s.v1 < 0 || s.v1 >= nv)
      throw std::invalid_argument("a boundary segment refers to a vertex that does not exist");
    if (s.group < 0 || s.group >= static_cast<int>(group_names_.size()))
      throw std::invalid_argument("a boundary segment has no valid group");
    if (s.curve >= static_cast<int>(curves_.size()))
      throw std::invalid_argument("a boundary segment refers to a curve that does not exist");
  }
  build_topology(segments);
}

void Mesh::build_topology(const std::vector<BoundarySegment>& segments) {
  struct HalfEdge {
    std::uint64_t key;
    int t;
    int k;
  };
  const int nt = num_triangles();
  std::vector<HalfEdge> half(3 * static_cast<std::size_t>(nt));
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const auto& tri = triangles_[t];
      half[3 * t + k] = {edge_key(tri[(k + 1) % 3], tri[(k + 2) % 3]), t, k};
    }
  std::sort(half.begin(), half.end(), [](const HalfEdge& a, const HalfEdge& b) {
    return a.key < b.key || (a.key == b.key && a.t < b.t);
  });
  triangle_edges_.assign(nt, {-1, -1, -1});
  triangle_edge_signs_.assign(nt, {0, 0, 0});
  std::vector<std::uint64_t> keys;
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].key == half[i].key) ++j;
    if (j - i > 2) throw std::invalid_argument("an edge is shared by more than two triangles");
    const int e = static_cast<int>(edges_.size());
    const auto& h0 = half[i];
    const auto& tri0 = triangles_[h0.t];
    int a = tri0[(h0.k + 1) % 3], b = tri0[(h0.k + 2) % 3];
    if (j - i == 2) {
      const auto& h1 = half[i + 1];
      const auto& tri1 = triangles_[h1.t];
      if (tri1[(h1.k + 1) % 3] != b)
        throw std::invalid_argument("two triangles sharing an edge have inconsistent orientation");
      std::array<int, 2> pq = {std::min(a, b), std::max(a, b)};
      edges_.push_back(pq);
      edge_triangles_.push_back({h0.t, h1.t});
      triangle_edges_[h0.t][h0.k] = e;
      triangle_edges_[h1.t][h1.k] = e;
      triangle_edge_signs_[h0.t][h0.k] = (a == pq[0]) ? 1 : -1;
      triangle_edge_signs_[h1.t][h1.k] = (tri1[(h1.k + 1) % 3] == pq[0]) ? 1 : -1;
    } else {
      edges_.push_back({a, b});
      edge_triangles_.push_back({h0.t, -1});
      triangle_edges_[h0.t][h0.k] = e;
      triangle_edge_signs_[h0.t][h0.k] = 1;
    }
    keys.push_back(h0.key);
    i = j;
  }
  edge_group_.assign(edges_.size(), -1);
  edge_curve_.assign(edges_.size(), -1);
  for (const auto& s : segments) {
    auto key = edge_key(s.v0, s.v1);
    auto it = std::lower_bound(keys.begin(), keys.end(), key);
    if (it == keys.end() || *it != key)
      throw std::invalid_argument("boundary segment (" + std::to_string(s.v0) + ", " +
                                  std::to_string(s.v1) + ") of group '" + group_names_[s.group] +
                                  "' is not an edge of the mesh");
    int e = static_cast<int>(it - keys.begin());
    if (edge_triangles_[e][1] >= 0)
      throw std::invalid_argument("boundary segment of group '" + group_names_[s.group] +
                                  "' lies inside the domain");
    if (edge_group_[e] >= 0 && edge_group_[e] != s.group)
      throw std::invalid_argument("a boundary edge belongs to two groups ('" +
                                  group_names_[edge_group_[e]] + "' and '" + group_names_[s.group] +
                                  "')");
    edge_group_[e] = s.group;
    edge_curve_[e] = s.curve;
  }
  for (int e = 0; e < num_edges(); ++e)
    if (edge_triangles_[e][1] < 0 && edge_group_[e] < 0) {
      const Point m = edge_midpoint(e);
      throw std::invalid_argument("the boundary edge at (" + std::to_string(m.x()) + ", " +
                                  std::to_string(m.y()) + ") belongs to no boundary group");
    }
}

Point Mesh::edge_normal(int e) const {
  Point d = vertices_[edges_[e][1]] - vertices_[edges_[e][0]];
  return Point(d.y(), -d.x()) / d.norm();
}

double Mesh::edge_length(int e) const {
  return (vertices_[edges_[e][1]] - vertices_[edges_[e][0]]).norm();
}

Point Mesh::edge_midpoint(int e) const {
  return 0.5 * (vertices_[edges_[e][0]] + vertices_[edges_[e][1]]);
}

double Mesh::triangle_area(int t) const {
  const auto& tri = triangles_[t];
  return signed_area(vertices_[tri[0]], vertices_[tri[1]], vertices_[tri[2]]);
}

int Mesh::group_index(const std::string& name) const {
  return group_index_.find(group_names_, name);
}

std::vector<std::vector<int>> Mesh::vertex_edges() const {
  std::vector<std::vector<int>> out(vertices_.size());
  for (int e = 0; e < num_edges(); ++e) {
    out[edges_[e][0]].push_back(e);
    out[edges_[e][1]].push_back(e);
  }
  return out;
}

double Mesh::diameter() const {
  double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
  for (const auto& p : vertices_) {
    lo_x = std::min(lo_x, p.x()), hi_x = std::max(hi_x, p.x());
    lo_y = std::min(lo_y, p.y()), hi_y = std::max(hi_y, p.y());
  }
  return std::hypot(hi_x - lo_x, hi_y - lo_y);
}

std::pair<double, double> Mesh::edge_length_range() const {
  double lo = std::numeric_limits<double>::max(), hi = 0.0;
  for (int e = 0; e < num_edges(); ++e) {
    double l = edge_length(e);
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  return {lo, hi};
}

}  // namespace fosls
