#pragma once
// gmsh MSH 4.1 ASCII text → its nodes, cells and boundary facets, for the 2D reader
// (msh_reader.hpp) and the 3D one (tet_msh_reader.hpp). Parsed here rather than by gmsh: the
// text comes from the network, and gmsh's global state is neither thread-safe nor meant for
// untrusted input. Every problem is a MeshError at /msh with a sentence naming the line.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace fosls {

/// A mesh of dimension d as the text holds it: cells are its triangles (d = 2, element type 2)
/// or tetrahedra (d = 3, type 4); facets are the lines (type 1) or triangles (type 2) on entities
/// of dimension d − 1, whose physical groups become boundary groups. Node tags are checked to
/// exist; nothing is checked about the mesh they make.
struct MshText {
  struct Node {
    Eigen::Vector3d x;
    int line_no;
  };
  struct Cell {
    std::array<std::uint64_t, 4> nodes;  ///< d + 1 of them
    int line_no;
  };
  struct Facet {
    long long entity;
    std::array<std::uint64_t, 3> nodes;  ///< d of them
    int line_no;
  };
  int dimension = 2;
  std::map<long long, std::string> names;  ///< physical names of dimension d − 1, by tag
  std::unordered_map<long long, std::vector<long long>> facet_entity_physicals;
  std::vector<long long> facet_physical_tags;
  std::unordered_map<std::uint64_t, Node> nodes;
  std::vector<Cell> cells;
  std::vector<Facet> facets;
};

/// Parses the text (corrupt, truncated or binary text, a wrong version, element types the
/// dimension cannot take, second-order elements, no cells at all: MeshError).
MshText parse_msh_text(std::string_view text, int dimension);

/// The boundary groups: every physical group of dimension d − 1, ordered by tag, named by its
/// physical name or else its tag; equal names share one group. Fills group_of_tag.
std::vector<std::string> msh_boundary_groups(const MshText& m,
                                             std::map<long long, int>& group_of_tag);

/// The group of a facet, −1 when its entity is in no physical group; a MeshError for an entity
/// that $Entities does not list or that is in several groups.
int msh_facet_group(const MshText& m, const MshText::Facet& f,
                    const std::map<long long, int>& group_of_tag);

/// The cells' nodes as vertices numbered in first-use order (nodes no cell uses are left
/// out): returns each cell's vertex indices (N = d + 1) and fills vertex_of_tag; each new
/// vertex's node is passed to `take` with its cell (which may refuse it by throwing).
template <int N, class Take>
std::vector<std::array<int, N>> number_cell_nodes(
    const MshText& m, std::unordered_map<std::uint64_t, int>& vertex_of_tag, Take take) {
  std::vector<std::array<int, N>> cells;
  for (const MshText::Cell& c : m.cells) {
    std::array<int, N> cell;
    for (int k = 0; k < N; ++k) {
      const auto [it, fresh] =
          vertex_of_tag.emplace(c.nodes[k], static_cast<int>(vertex_of_tag.size()));
      if (fresh) take(c.nodes[k], m.nodes.at(c.nodes[k]), c);
      cell[k] = it->second;
    }
    cells.push_back(cell);
  }
  return cells;
}

/// MeshError at /msh: "line N: what." and "What.".
[[noreturn]] void throw_msh_error_at(int line_no, const std::string& what);
[[noreturn]] void throw_msh_error(const std::string& what);
/// A coordinate in an error message (six significant digits).
std::string msh_number(double v);

}  // namespace fosls
