#include "mesh/msh_reader.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/msh_text.hpp"

namespace fosls {

namespace {

/// Every boundary edge of the triangulation must be on a physical curve.
void check_boundary_covered(const std::vector<Point>& vertices,
                            const std::vector<std::array<int, 3>>& triangles,
                            const std::vector<BoundarySegment>& segments) {
  auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
           static_cast<std::uint64_t>(std::max(a, b));
  };
  std::vector<std::uint64_t> edges;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) edges.push_back(key(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint64_t> covered;
  for (const auto& s : segments) covered.push_back(key(s.v0, s.v1));
  std::sort(covered.begin(), covered.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1 && !std::binary_search(covered.begin(), covered.end(), edges[i])) {
      const Point a = vertices[edges[i] >> 32], b = vertices[edges[i] & 0xffffffffu];
      throw_msh_error("the boundary edge from (" + msh_number(a.x()) + ", " + msh_number(a.y()) +
                      ") to (" + msh_number(b.x()) + ", " + msh_number(b.y()) +
                      ") is on no physical curve; put every boundary curve in a physical group "
                      "(Physical Curve) before saving the mesh");
    }
    i = j;
  }
}

}  // namespace

Mesh mesh_from_msh(std::string_view text) {
  const MshText m = parse_msh_text(text, 2);
  std::unordered_map<std::uint64_t, int> vertex_of_tag;
  std::vector<Point> vertices;
  std::vector<std::array<int, 3>> triangles = number_cell_nodes<3>(
      m, vertex_of_tag,
      [&vertices](std::uint64_t tag, const MshText::Node& node, const MshText::Cell& c) {
        if (node.x.z() != 0.0)
          throw_msh_error_at(c.line_no, "the triangle uses node " + std::to_string(tag) +
                                            " (line " + std::to_string(node.line_no) +
                                            ") with z = " + msh_number(node.x.z()) +
                                            "; only planar meshes in z = 0 are supported");
        vertices.emplace_back(node.x.x(), node.x.y());
      });
  std::map<long long, int> group_of_tag;
  std::vector<std::string> group_names = msh_boundary_groups(m, group_of_tag);
  std::vector<BoundarySegment> segments;
  for (const MshText::Facet& f : m.facets) {
    const int group = msh_facet_group(m, f, group_of_tag);
    if (group < 0) continue;  // not on a physical curve: caught below if on the boundary
    const auto v0 = vertex_of_tag.find(f.nodes[0]), v1 = vertex_of_tag.find(f.nodes[1]);
    if (v0 == vertex_of_tag.end() || v1 == vertex_of_tag.end())
      throw_msh_error_at(f.line_no, "the line element uses a node that belongs to no triangle");
    segments.push_back({v0->second, v1->second, group, -1});
  }
  check_boundary_covered(vertices, triangles, segments);
  try {
    return Mesh(std::move(vertices), std::move(triangles), std::move(segments),
                std::move(group_names));
  } catch (const std::invalid_argument& e) {
    throw_msh_error(std::string("the mesh is not a valid triangulation: ") + e.what());
  }
}

}  // namespace fosls
