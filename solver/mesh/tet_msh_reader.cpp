#include "mesh/tet_msh_reader.hpp"

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "mesh/msh_text.hpp"

namespace fosls {

namespace {

std::string corners(const TetMesh& mesh, int f) {
  std::string s;
  for (int v : mesh.face(f)) {
    const Point3& x = mesh.vertex(v);
    s += (s.empty() ? "(" : ", (") + msh_number(x.x()) + ", " + msh_number(x.y()) + ", " +
         msh_number(x.z()) + ")";
  }
  return s;
}

/// Boundary groups exactly on the boundary: every boundary face in one, no interior face in any.
void check_groups_on_boundary(const TetMesh& mesh) {
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const bool boundary = mesh.is_boundary_face(f), grouped = mesh.face_group(f) >= 0;
    if (boundary && !grouped)
      throw_msh_error("the boundary face with corners " + corners(mesh, f) +
                      " is on no physical surface; put every boundary surface in a physical "
                      "group (Physical Surface) before saving the mesh");
    if (!boundary && grouped)
      throw_msh_error("the face with corners " + corners(mesh, f) + " of physical surface '" +
                      mesh.group_names()[mesh.face_group(f)] +
                      "' lies between two tetrahedra; boundary groups must be on the boundary "
                      "of the body");
  }
}

/// Every physical-surface triangle is a face of the mesh (not, say, of a non-conforming one).
void check_faces_exist(const TetMesh& mesh, const std::vector<BoundaryFace>& boundary,
                       const std::vector<int>& lines) {
  std::unordered_set<long long> faces;
  for (int f = 0; f < mesh.num_faces(); ++f) faces.insert(face_key(mesh.face(f)));
  for (std::size_t k = 0; k < boundary.size(); ++k)
    if (!faces.count(face_key(boundary[k].vertices)))
      throw_msh_error_at(lines[k],
                         "the triangle is not a face of any tetrahedron (the surface "
                         "mesh does not match the volume mesh)");
}

}  // namespace

TetMesh tet_mesh_from_msh(std::string_view text) {
  const MshText m = parse_msh_text(text, 3);
  std::unordered_map<std::uint64_t, int> vertex_of_tag;
  std::vector<Point3> vertices;
  std::vector<std::array<int, 4>> tets =
      number_cell_nodes<4>(m, vertex_of_tag,
                           [&vertices](std::uint64_t, const MshText::Node& node,
                                       const MshText::Cell&) { vertices.push_back(node.x); });
  std::map<long long, int> group_of_tag;
  std::vector<std::string> group_names = msh_boundary_groups(m, group_of_tag);
  std::vector<BoundaryFace> boundary;
  std::vector<int> boundary_lines;
  for (const MshText::Facet& f : m.facets) {
    const int group = msh_facet_group(m, f, group_of_tag);
    if (group < 0) continue;  // on no physical surface: caught below if on the boundary
    BoundaryFace b{{}, group};
    for (int k = 0; k < 3; ++k) {
      const auto v = vertex_of_tag.find(f.nodes[k]);
      if (v == vertex_of_tag.end())
        throw_msh_error_at(f.line_no, "the triangle uses node " + std::to_string(f.nodes[k]) +
                                          ", which belongs to no tetrahedron");
      b.vertices[k] = v->second;
    }
    boundary.push_back(b);
    boundary_lines.push_back(f.line_no);
  }
  try {
    TetMesh mesh(std::move(vertices), std::move(tets), boundary, std::move(group_names));
    check_faces_exist(mesh, boundary, boundary_lines);
    check_groups_on_boundary(mesh);
    return mesh;
  } catch (const std::invalid_argument& e) {
    throw_msh_error(std::string("the mesh is not a valid tetrahedral mesh: ") + e.what());
  }
}

}  // namespace fosls
