#include "mesh/msh_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/mesh_error.hpp"

namespace fosls {

namespace {

const std::string kField = "/msh";  // relative to the mesh section

std::string quote(std::string_view s) {
  constexpr std::size_t kMax = 40;
  std::string out(s.substr(0, kMax));
  if (s.size() > kMax) out += "...";
  return "'" + out + "'";
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    std::size_t j = i;
    while (j < line.size() && !is_space(line[j])) ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

bool is_second_order(long long type) {
  // Curved or higher-order lines and triangles (and their incomplete variants).
  static const int kTypes[] = {8, 9, 16, 20, 21, 22, 23, 24, 25, 26, 27, 28};
  return std::find(std::begin(kTypes), std::end(kTypes), type) != std::end(kTypes);
}

/// A line element waiting for $Entities and the node map: its curve entity and where it was.
struct PendingLine {
  long long entity;
  std::uint64_t n0, n1;
  int line_no;
};

struct Node {
  Point xy;
  double z;
  int line_no;
};

/// Line-oriented MSH 4.1 ASCII parser. Counts read from the text are checked against the text
/// that is left before anything is stored, so a corrupt count cannot make it allocate much.
class MshParser {
 public:
  explicit MshParser(std::string_view text) : text_(text) {}

  Mesh parse() {
    if (text_.find_first_not_of(" \t\r\n\v\f") == std::string_view::npos)
      throw MeshError(kField, "the msh text is empty; expected a gmsh MSH 4.1 ASCII mesh");
    read_mesh_format();
    std::string_view line;
    while (next_line(line)) {
      auto tok = split(line);
      const std::string_view name = tok[0];
      if (name.empty() || name[0] != '$')
        fail("expected a section header such as $Nodes or $Elements, found " + quote(line));
      if (name == "$MeshFormat") fail("found a second $MeshFormat section");
      if (name == "$PhysicalNames") {
        once(seen_names_, name);
        read_physical_names();
      } else if (name == "$Entities") {
        once(seen_entities_, name);
        read_entities();
      } else if (name == "$PartitionedEntities") {
        fail("partitioned meshes are not supported; save the mesh without partitions");
      } else if (name == "$Nodes") {
        once(seen_nodes_, name);
        read_nodes();
      } else if (name == "$Elements") {
        once(seen_elements_, name);
        if (!seen_nodes_) fail("$Elements comes before $Nodes; expected $Nodes first");
        read_elements();
      } else {
        skip_section(name);
      }
    }
    if (!seen_nodes_) fail_at_end("the msh text has no $Nodes section");
    if (!seen_elements_) fail_at_end("the msh text has no $Elements section");
    return build();
  }

 private:
  // ---- lines -----------------------------------------------------------------------------

  /// Next non-blank line (without its end of line); false at the end of the text.
  bool next_line(std::string_view& line) {
    while (pos_ < text_.size()) {
      std::size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_no_;
      if (!split(line).empty()) {
        line_ = line;
        return true;
      }
    }
    return false;
  }

  /// The tokens of the next line; `what` names what the line should hold.
  std::vector<std::string_view> expect_line(const std::string& what) {
    std::string_view line;
    if (!next_line(line))
      fail_at_end("the msh text ends inside " + section_ + " at line " + std::to_string(line_no_) +
                  "; expected " + what + " (the text is truncated)");
    auto tok = split(line);
    // Data lines never start with '$': a header here means the section ended early.
    if (tok[0][0] == '$')
      fail("expected " + what + ", found " + quote(line) + " (the section ends early)");
    return tok;
  }

  [[noreturn]] void fail(const std::string& what) const {
    // On the last line a malformed record usually means the text was cut off.
    const bool last = section_ != "$MeshFormat" &&
                      text_.find_first_not_of(" \t\r\n\v\f", std::min(pos_, text_.size())) ==
                          std::string_view::npos;
    throw MeshError(kField, "line " + std::to_string(line_no_) + ": " + what +
                                (last ? " (the text ends here: it is truncated)." : "."));
  }
  [[noreturn]] void fail_at(int line_no, const std::string& what) const {
    throw MeshError(kField, "line " + std::to_string(line_no) + ": " + what + ".");
  }
  [[noreturn]] void fail_at_end(const std::string& what) const {
    throw MeshError(kField, what + ".");
  }

  void once(bool& seen, std::string_view name) {
    if (seen) fail("found a second " + std::string(name) + " section");
    seen = true;
    section_ = std::string(name);
  }

  void expect_end(const std::string& end) {
    std::string_view line;
    if (!next_line(line))
      fail_at_end("the msh text ends at line " + std::to_string(line_no_) + " without " + end);
    if (split(line)[0] != end) fail("expected " + end + ", found " + quote(line));
  }

  void skip_section(std::string_view name) {
    section_ = std::string(name);
    const std::string end = "$End" + std::string(name.substr(1));
    std::string_view line;
    while (next_line(line))
      if (split(line)[0] == end) return;
    fail_at_end("the section " + std::string(name) + " is never closed; expected " + end);
  }

  // ---- numbers ---------------------------------------------------------------------------

  long long integer(const std::vector<std::string_view>& tok, std::size_t i,
                    const std::string& what) const {
    if (i >= tok.size()) fail("expected " + what + " (an integer), but the line ends early");
    std::string_view s = tok[i];
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    long long v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size())
      fail("expected " + what + " (an integer), found " + quote(tok[i]));
    return v;
  }

  double real(const std::vector<std::string_view>& tok, std::size_t i,
              const std::string& what) const {
    if (i >= tok.size()) fail("expected " + what + " (a number), but the line ends early");
    std::string_view s = tok[i];
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    double v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v))
      fail("expected " + what + " (a finite number), found " + quote(tok[i]));
    return v;
  }

  /// A count of records, each at least `min_bytes` long, that must fit in the remaining text.
  long long count(const std::vector<std::string_view>& tok, std::size_t i, const std::string& what,
                  std::size_t min_bytes) const {
    const long long n = integer(tok, i, what);
    if (n < 0) fail("expected " + what + " (a count, not negative), found " + quote(tok[i]));
    const std::size_t left = pos_ < text_.size() ? text_.size() - pos_ : 0;
    if (static_cast<unsigned long long>(n) > left / min_bytes)
      fail(what + " is " + std::to_string(n) + ", more than the remaining " + std::to_string(left) +
           " bytes of text can hold (the text is corrupt or truncated)");
    return n;
  }

  void expect_tokens(const std::vector<std::string_view>& tok, std::size_t n,
                     const std::string& what) const {
    if (tok.size() != n)
      fail("expected " + what + " (" + std::to_string(n) + " values), found " +
           std::to_string(tok.size()) + " values");
  }

  // ---- sections --------------------------------------------------------------------------

  void read_mesh_format() {
    section_ = "$MeshFormat";
    std::string_view line;
    next_line(line);
    if (split(line)[0] != "$MeshFormat")
      fail("expected $MeshFormat (the start of a gmsh MSH 4.1 ASCII mesh), found " + quote(line));
    auto tok = expect_line("the format line '4.1 0 8'");
    if (tok.size() < 3) fail("expected the format line '4.1 0 8' (version, file type, data size)");
    if (tok[0] != "4.1")
      fail("the msh version is " + quote(tok[0]) +
           "; only version 4.1 is supported (save with Mesh.MshFileVersion = 4.1)");
    const long long file_type = integer(tok, 1, "the file type");
    if (file_type == 1)
      fail("the mesh is binary; only ASCII is supported (save with Mesh.Binary = 0)");
    if (file_type != 0) fail("expected file type 0 (ASCII), found " + quote(tok[1]));
    integer(tok, 2, "the data size");
    expect_end("$EndMeshFormat");
  }

  void read_physical_names() {
    auto tok = expect_line("the number of physical names");
    expect_tokens(tok, 1, "the number of physical names");
    const long long n = count(tok, 0, "the number of physical names", 7);
    for (long long i = 0; i < n; ++i) {
      tok = expect_line("a physical name 'dimension tag \"name\"'");
      const long long dim = integer(tok, 0, "the dimension of the physical group");
      const long long tag = integer(tok, 1, "the tag of the physical group");
      // The name is the rest of the line in double quotes and may contain spaces.
      const std::string_view line = line_;
      const std::size_t open = line.find('"'), close = line.rfind('"');
      if (open == std::string_view::npos || close == open)
        fail("expected the name of physical group " + std::to_string(tag) + " in double quotes");
      if (dim == 1) names_[tag] = std::string(line.substr(open + 1, close - open - 1));
    }
    expect_end("$EndPhysicalNames");
  }

  void read_entities() {
    auto tok = expect_line("the entity counts 'points curves surfaces volumes'");
    expect_tokens(tok, 4, "the entity counts 'points curves surfaces volumes'");
    long long n[4];
    for (int d = 0; d < 4; ++d) n[d] = count(tok, d, "the number of entities", 10);
    for (int d = 0; d < 4; ++d)
      for (long long i = 0; i < n[d]; ++i) {
        tok = expect_line(d == 0 ? "a point entity" : "an entity 'tag box physicals boundary'");
        const long long tag = integer(tok, 0, "the entity tag");
        // Points: tag x y z; others: tag and a bounding box of six numbers.
        const std::size_t at = d == 0 ? 4 : 7;
        for (std::size_t k = 1; k < at; ++k) real(tok, k, "a coordinate of the entity");
        const long long np = integer(tok, at, "the number of physical tags");
        if (np < 0 || static_cast<std::size_t>(np) > tok.size() - at - 1)
          fail("the entity lists " + std::to_string(np) + " physical tags but the line holds " +
               "fewer");
        std::vector<long long> phys;
        for (long long k = 0; k < np; ++k)
          phys.push_back(integer(tok, at + 1 + k, "a physical tag"));
        if (d == 1) {
          if (!curve_physicals_.emplace(tag, phys).second)
            fail("curve entity " + std::to_string(tag) + " is listed twice");
          for (long long p : phys) curve_physical_tags_.push_back(p);
        }
      }
    expect_end("$EndEntities");
  }

  void read_nodes() {
    auto tok = expect_line("the node counts 'blocks nodes min-tag max-tag'");
    expect_tokens(tok, 4, "the node counts 'blocks nodes min-tag max-tag'");
    const long long blocks = count(tok, 0, "the number of node blocks", 8);
    const long long total = count(tok, 1, "the number of nodes", 8);
    long long read = 0;
    for (long long b = 0; b < blocks; ++b) {
      tok = expect_line("a node block header 'dimension entity parametric count'");
      expect_tokens(tok, 4, "a node block header 'dimension entity parametric count'");
      const long long dim = integer(tok, 0, "the entity dimension");
      if (dim < 0 || dim > 3) fail("expected an entity dimension 0 to 3, found " + quote(tok[0]));
      integer(tok, 1, "the entity tag");
      const long long parametric = integer(tok, 2, "the parametric flag");
      if (parametric != 0 && parametric != 1)
        fail("expected the parametric flag 0 or 1, found " + quote(tok[2]));
      const long long n = count(tok, 3, "the number of nodes in the block", 8);
      if (read + n > total)
        fail("the node blocks hold more nodes than the " + std::to_string(total) + " announced");
      std::vector<std::pair<std::uint64_t, int>> tags;
      for (long long i = 0; i < n; ++i) {
        tok = expect_line("a node tag");
        expect_tokens(tok, 1, "a node tag");
        const long long tag = integer(tok, 0, "a node tag");
        if (tag <= 0) fail("expected a positive node tag, found " + quote(tok[0]));
        tags.emplace_back(static_cast<std::uint64_t>(tag), line_no_);
      }
      for (long long i = 0; i < n; ++i) {
        tok = expect_line("the coordinates 'x y z' of node " + std::to_string(tags[i].first));
        if (tok.size() < 3)
          fail("expected the coordinates 'x y z' of node " + std::to_string(tags[i].first));
        const double x = real(tok, 0, "the x coordinate");
        const double y = real(tok, 1, "the y coordinate");
        const double z = real(tok, 2, "the z coordinate");
        if (!nodes_.emplace(tags[i].first, Node{Point(x, y), z, line_no_}).second)
          fail_at(tags[i].second, "node tag " + std::to_string(tags[i].first) + " is used twice");
      }
      read += n;
    }
    if (read != total)
      fail("the node blocks hold " + std::to_string(read) + " nodes but " + std::to_string(total) +
           " were announced");
    expect_end("$EndNodes");
  }

  void read_elements() {
    auto tok = expect_line("the element counts 'blocks elements min-tag max-tag'");
    expect_tokens(tok, 4, "the element counts 'blocks elements min-tag max-tag'");
    const long long blocks = count(tok, 0, "the number of element blocks", 8);
    const long long total = count(tok, 1, "the number of elements", 4);
    long long read = 0;
    for (long long b = 0; b < blocks; ++b) {
      tok = expect_line("an element block header 'dimension entity type count'");
      expect_tokens(tok, 4, "an element block header 'dimension entity type count'");
      const long long dim = integer(tok, 0, "the entity dimension");
      const long long entity = integer(tok, 1, "the entity tag");
      const long long type = integer(tok, 2, "the element type");
      const long long n = count(tok, 3, "the number of elements in the block", 4);
      if (read + n > total)
        fail("the element blocks hold more elements than the " + std::to_string(total) +
             " announced");
      if (type == 3)
        fail("quadrangles (element type 3) are not supported; mesh with triangles only");
      if (is_second_order(type))
        fail("element type " + std::to_string(type) +
             " is a second-order element; only first-order meshes are supported (save with "
             "Mesh.ElementOrder = 1)");
      if ((type == 1 && dim != 1) || (type == 2 && dim != 2))
        fail("element type " + std::to_string(type) + " in a block of dimension " +
             std::to_string(dim));
      for (long long i = 0; i < n; ++i) {
        tok = expect_line("an element 'tag node...'");
        integer(tok, 0, "the element tag");
        if (type == 2) {
          expect_tokens(tok, 4, "a triangle 'tag node node node'");
          triangles_.push_back({node_index(tok, 1), node_index(tok, 2), node_index(tok, 3)});
        } else if (type == 1) {
          expect_tokens(tok, 3, "a line element 'tag node node'");
          lines_.push_back({entity, node_tag(tok, 1), node_tag(tok, 2), line_no_});
        }
        // Points (type 15) and elements of other dimensions carry nothing a 2D mesh needs.
      }
      read += n;
    }
    if (read != total)
      fail("the element blocks hold " + std::to_string(read) + " elements but " +
           std::to_string(total) + " were announced");
    expect_end("$EndElements");
  }

  std::uint64_t node_tag(const std::vector<std::string_view>& tok, std::size_t i) {
    const long long tag = integer(tok, i, "a node tag");
    if (tag <= 0 || nodes_.find(static_cast<std::uint64_t>(tag)) == nodes_.end())
      fail("the element refers to node " + quote(tok[i]) + ", which is not in $Nodes");
    return static_cast<std::uint64_t>(tag);
  }

  /// Index of a triangle's node among the mesh vertices (triangle nodes only, in first-use order).
  int node_index(const std::vector<std::string_view>& tok, std::size_t i) {
    const std::uint64_t tag = node_tag(tok, i);
    auto [it, fresh] = vertex_of_tag_.emplace(tag, static_cast<int>(vertices_.size()));
    if (fresh) {
      const Node& node = nodes_.at(tag);
      if (node.z != 0.0)
        fail("the triangle uses node " + std::to_string(tag) + " (line " +
             std::to_string(node.line_no) + ") with z = " + num(node.z) +
             "; only planar meshes in z = 0 are supported");
      vertices_.push_back(node.xy);
    }
    return it->second;
  }

  // ---- assembly --------------------------------------------------------------------------

  Mesh build() {
    if (triangles_.empty())
      fail_at_end(
          "the msh text has no triangles (element type 2); it must hold a 2D triangle "
          "mesh (when the file has physical groups, gmsh saves only their elements: put "
          "the surface in a Physical Surface too)");

    // Groups: every physical curve, ordered by tag; equal names share one group.
    std::vector<long long> tags = curve_physical_tags_;
    for (const auto& [tag, name] : names_) tags.push_back(tag);
    std::sort(tags.begin(), tags.end());
    tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
    std::vector<std::string> group_names;
    std::map<long long, int> group_of_tag;
    for (long long tag : tags) {
      auto it = names_.find(tag);
      std::string name = it != names_.end() ? it->second : std::to_string(tag);
      auto pos = std::find(group_names.begin(), group_names.end(), name);
      group_of_tag[tag] = static_cast<int>(pos - group_names.begin());
      if (pos == group_names.end()) group_names.push_back(name);
    }

    std::vector<BoundarySegment> segments;
    for (const auto& ln : lines_) {
      auto ent = curve_physicals_.find(ln.entity);
      if (ent == curve_physicals_.end())
        fail_at(ln.line_no, "the line element lies on curve entity " + std::to_string(ln.entity) +
                                ", which is not listed in $Entities, so its physical group is "
                                "unknown");
      const auto& phys = ent->second;
      if (phys.empty()) continue;  // not on a physical curve: caught below if on the boundary
      if (phys.size() > 1)
        fail_at(ln.line_no, "curve entity " + std::to_string(ln.entity) + " is in " +
                                std::to_string(phys.size()) +
                                " physical groups; every boundary curve must be in exactly one");
      auto v0 = vertex_of_tag_.find(ln.n0), v1 = vertex_of_tag_.find(ln.n1);
      if (v0 == vertex_of_tag_.end() || v1 == vertex_of_tag_.end())
        fail_at(ln.line_no, "the line element uses a node that belongs to no triangle");
      segments.push_back({v0->second, v1->second, group_of_tag.at(phys[0]), -1});
    }
    check_boundary_covered(segments);
    try {
      return Mesh(std::move(vertices_), std::move(triangles_), std::move(segments),
                  std::move(group_names));
    } catch (const std::invalid_argument& e) {
      fail_at_end(std::string("the mesh is not a valid triangulation: ") + e.what());
    }
  }

  /// Every boundary edge of the triangulation must be on a physical curve.
  void check_boundary_covered(const std::vector<BoundarySegment>& segments) const {
    auto key = [](int a, int b) {
      return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
             static_cast<std::uint64_t>(std::max(a, b));
    };
    std::vector<std::uint64_t> edges;
    for (const auto& t : triangles_)
      for (int k = 0; k < 3; ++k) edges.push_back(key(t[k], t[(k + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    std::vector<std::uint64_t> covered;
    for (const auto& s : segments) covered.push_back(key(s.v0, s.v1));
    std::sort(covered.begin(), covered.end());
    for (std::size_t i = 0; i < edges.size();) {
      std::size_t j = i;
      while (j < edges.size() && edges[j] == edges[i]) ++j;
      if (j - i == 1 && !std::binary_search(covered.begin(), covered.end(), edges[i])) {
        const Point a = vertices_[edges[i] >> 32], b = vertices_[edges[i] & 0xffffffffu];
        fail_at_end("the boundary edge from (" + num(a.x()) + ", " + num(a.y()) + ") to (" +
                    num(b.x()) + ", " + num(b.y()) +
                    ") is on no physical curve; put every boundary curve in a physical group "
                    "(Physical Curve) before saving the mesh");
      }
      i = j;
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int line_no_ = 0;
  std::string_view line_;  ///< the line last returned by next_line
  std::string section_;
  bool seen_names_ = false, seen_entities_ = false, seen_nodes_ = false, seen_elements_ = false;

  std::map<long long, std::string> names_;  ///< dimension-1 physical names by tag
  std::unordered_map<long long, std::vector<long long>> curve_physicals_;
  std::vector<long long> curve_physical_tags_;
  std::unordered_map<std::uint64_t, Node> nodes_;
  std::unordered_map<std::uint64_t, int> vertex_of_tag_;
  std::vector<Point> vertices_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<PendingLine> lines_;
};

}  // namespace

Mesh mesh_from_msh(std::string_view text) { return MshParser(text).parse(); }

}  // namespace fosls
