#include "mesh/msh_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

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

bool is_second_order(long long type, int dimension) {
  // Curved or higher-order lines and triangles (and their incomplete variants); in 3D also
  // tetrahedra.
  static const int kTypes[] = {8, 9, 16, 20, 21, 22, 23, 24, 25, 26, 27, 28};
  static const int kTets[] = {11, 29, 30, 31};
  return std::find(std::begin(kTypes), std::end(kTypes), type) != std::end(kTypes) ||
         (dimension == 3 && std::find(std::begin(kTets), std::end(kTets), type) != std::end(kTets));
}

const char* facet_entity_word(int dimension) { return dimension == 2 ? "curve" : "surface"; }

/// Line-oriented MSH 4.1 ASCII parser. Counts read from the text are checked against the text
/// that is left before anything is stored, so a corrupt count cannot make it allocate much.
class MshParser {
 public:
  MshParser(std::string_view text, int dimension) : text_(text) { out_.dimension = dimension; }

  MshText parse() {
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
    return std::move(out_);
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
    throw_msh_error_at(line_no, what);
  }
  [[noreturn]] void fail_at_end(const std::string& what) const { throw_msh_error(what); }

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
      if (dim == out_.dimension - 1)
        out_.names[tag] = std::string(line.substr(open + 1, close - open - 1));
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
        if (d == out_.dimension - 1) {
          if (!out_.facet_entity_physicals.emplace(tag, phys).second)
            fail(std::string(facet_entity_word(out_.dimension)) + " entity " + std::to_string(tag) +
                 " is listed twice");
          for (long long p : phys) out_.facet_physical_tags.push_back(p);
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
        if (!out_.nodes.emplace(tags[i].first, MshText::Node{Eigen::Vector3d(x, y, z), line_no_})
                 .second)
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
      check_element_type(dim, type);
      const bool cell = type == cell_type(), facet = type == facet_type();
      for (long long i = 0; i < n; ++i) {
        tok = expect_line("an element 'tag node...'");
        integer(tok, 0, "the element tag");
        if (cell) {
          expect_tokens(tok, out_.dimension + 2,
                        out_.dimension == 2 ? "a triangle 'tag node node node'"
                                            : "a tetrahedron 'tag node node node node'");
          MshText::Cell c{{}, line_no_};
          for (int k = 0; k <= out_.dimension; ++k) c.nodes[k] = node_tag(tok, k + 1);
          out_.cells.push_back(c);
        } else if (facet) {
          expect_tokens(tok, out_.dimension + 1,
                        out_.dimension == 2 ? "a line element 'tag node node'"
                                            : "a triangle 'tag node node node'");
          MshText::Facet f{entity, {}, line_no_};
          for (int k = 0; k < out_.dimension; ++k) f.nodes[k] = node_tag(tok, k + 1);
          out_.facets.push_back(f);
        }
        // Points (type 15) and elements of other dimensions carry nothing the mesh needs.
      }
      read += n;
    }
    if (read != total)
      fail("the element blocks hold " + std::to_string(read) + " elements but " +
           std::to_string(total) + " were announced");
    expect_end("$EndElements");
  }

  /// Triangles and their lines in 2D, tetrahedra and their triangles in 3D.
  int cell_type() const { return out_.dimension == 2 ? 2 : 4; }
  int facet_type() const { return out_.dimension == 2 ? 1 : 2; }

  /// Refuses the element types a mesh of this dimension cannot take, with what to do instead.
  void check_element_type(long long dim, long long type) const {
    const bool three = out_.dimension == 3;
    if (type == 3)
      fail(std::string("quadrangles (element type 3) are not supported; mesh with ") +
           (three ? "tetrahedra" : "triangles") + " only");
    if (three && type >= 5 && type <= 7)
      fail("element type " + std::to_string(type) +
           " (hexahedra, prisms or pyramids) is not supported; mesh with tetrahedra only");
    if (is_second_order(type, out_.dimension))
      fail("element type " + std::to_string(type) +
           " is a second-order element; only first-order meshes are supported (save with "
           "Mesh.ElementOrder = 1)");
    if ((type == 1 && dim != 1) || (type == 2 && dim != 2) || (three && type == 4 && dim != 3))
      fail("element type " + std::to_string(type) + " in a block of dimension " +
           std::to_string(dim));
  }

  std::uint64_t node_tag(const std::vector<std::string_view>& tok, std::size_t i) {
    const long long tag = integer(tok, i, "a node tag");
    if (tag <= 0 || out_.nodes.find(static_cast<std::uint64_t>(tag)) == out_.nodes.end())
      fail("the element refers to node " + quote(tok[i]) + ", which is not in $Nodes");
    return static_cast<std::uint64_t>(tag);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int line_no_ = 0;
  std::string_view line_;  ///< the line last returned by next_line
  std::string section_;
  bool seen_names_ = false, seen_entities_ = false, seen_nodes_ = false, seen_elements_ = false;
  MshText out_;
};

}  // namespace

MshText parse_msh_text(std::string_view text, int dimension) {
  if (dimension != 2 && dimension != 3) throw std::logic_error("parse_msh_text: dimension 2 or 3");
  MshText m = MshParser(text, dimension).parse();
  if (m.cells.empty())
    throw_msh_error(
        dimension == 2
            ? "the msh text has no triangles (element type 2); it must hold a 2D triangle "
              "mesh (when the file has physical groups, gmsh saves only their elements: put "
              "the surface in a Physical Surface too)"
            : "the msh text has no tetrahedra (element type 4); it must hold a 3D tetrahedral "
              "mesh (when the file has physical groups, gmsh saves only their elements: put the "
              "volume in a Physical Volume too)");
  return m;
}

void throw_msh_error_at(int line_no, const std::string& what) {
  throw MeshError(kField, "line " + std::to_string(line_no) + ": " + what + ".");
}

void throw_msh_error(const std::string& what) { throw MeshError(kField, what + "."); }

std::string msh_number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::vector<std::string> msh_boundary_groups(const MshText& m,
                                             std::map<long long, int>& group_of_tag) {
  std::vector<long long> tags = m.facet_physical_tags;
  for (const auto& [tag, name] : m.names) tags.push_back(tag);
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  std::vector<std::string> names;
  // Equal names are found by hash: a text may hold hundreds of thousands of them.
  std::unordered_map<std::string, int> group_of_name;
  group_of_name.reserve(tags.size());
  for (long long tag : tags) {
    const auto it = m.names.find(tag);
    std::string name = it != m.names.end() ? it->second : std::to_string(tag);
    const auto [known, added] = group_of_name.emplace(name, static_cast<int>(names.size()));
    group_of_tag[tag] = known->second;
    if (added) names.push_back(std::move(name));
  }
  return names;
}

int msh_facet_group(const MshText& m, const MshText::Facet& f,
                    const std::map<long long, int>& group_of_tag) {
  const std::string entity = facet_entity_word(m.dimension);
  const auto ent = m.facet_entity_physicals.find(f.entity);
  if (ent == m.facet_entity_physicals.end())
    throw_msh_error_at(f.line_no,
                       std::string(m.dimension == 2 ? "the line element" : "the triangle") +
                           " lies on " + entity + " entity " + std::to_string(f.entity) +
                           ", which is not listed in $Entities, so its physical group "
                           "is unknown");
  const auto& phys = ent->second;
  if (phys.empty()) return -1;  // on no physical group: the caller decides whether that matters
  if (phys.size() > 1)
    throw_msh_error_at(f.line_no, entity + " entity " + std::to_string(f.entity) + " is in " +
                                      std::to_string(phys.size()) + " physical groups; every " +
                                      "boundary " + entity + " must be in exactly one");
  return group_of_tag.at(phys[0]);
}

}  // namespace fosls
