// The `mesh` section: one source (builtin, geometry, msh or geo_file), the coarse size and the
// number of refinements.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>

#include "case/format/case_sections.hpp"
#include "case/format/rule_checker.hpp"
#include "mesh/builtin_meshes.hpp"
#include "mesh/coarse_mesh_estimate.hpp"

namespace fosls {

namespace {

using nlohmann::json;

bool check_msh_text(const json& j, const std::string& pointer, RuleChecker& checker) {
  const auto& text = j.get_ref<const std::string&>();
  const auto start = text.find_first_not_of(" \t\r\n");
  if (start == std::string::npos) {
    checker.error(pointer, "the msh text is empty; give the contents of a gmsh .msh file");
    return false;
  }
  if (text.compare(start, 11, "$MeshFormat") != 0) {
    checker.error(pointer,
                  "this is not gmsh .msh text: it must start with $MeshFormat (save the mesh "
                  "from gmsh in ASCII format 4.1)");
    return false;
  }
  return true;
}

/// A local file named by the case: the command line only (see CaseReadOptions).
bool check_local_file(const json& j, const std::string& pointer, RuleChecker& checker,
                      const char* what) {
  if (!checker.options().allow_local_files) {
    checker.error(pointer, std::string("a ") + what +
                               " path is accepted only by the command line program "
                               "(fosls-contact solve): the service reads no files named by a "
                               "case, and gmsh scripts can run shell commands; give the mesh "
                               "as text in mesh.msh (or, in 2D, as mesh.geometry) instead");
    return false;
  }
  const auto& path = j.get_ref<const std::string&>();
  if (path.empty()) {
    checker.error(pointer, std::string("the path is empty; give the path of a ") + what);
    return false;
  }
  if (path.find('\0') != std::string::npos) {
    checker.error(pointer, "the path contains a NUL character");
    return false;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    checker.error(pointer, "no such file: " + path +
                               " (a relative path is taken relative to the case file's folder)");
    return false;
  }
  return true;
}

/// The text of a file, at most `max_bytes` + 1 bytes of it (so that a larger file shows), or
/// nothing when it cannot be read.
std::optional<std::string> read_text_file(const std::string& path, std::size_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text;
  char buffer[1 << 16];
  while (in && text.size() <= max_bytes) {
    in.read(buffer, sizeof buffer);
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) return std::nullopt;
  return text;
}

/// A tiny `size` must not build a huge coarse mesh before the DOF limit can be checked: the
/// mesh layer's estimate and limits, checked before anything is meshed (2D: a 3D builtin's size
/// is its cells, and a .geo file's is known once meshed).
void check_coarse_size(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!checker.usable(j, pointer, {"size"})) return;
  const double size = j.value("size", MeshSpec{}.size);
  const std::string size_pointer = child_pointer(pointer, "size");
  if (j.contains("geometry") && checker.passed(child_pointer(pointer, "geometry"))) {
    const auto problems = check_coarse_mesh_estimate(
        estimated_coarse_mesh(read_geometry_section(j["geometry"]), size));
    for (const auto& p : problems) checker.error(size_pointer, p.detail);
    return;
  }
  if (!j.contains("builtin") || !checker.passed(child_pointer(pointer, "builtin"))) return;
  const double triangles = builtin_triangles(j["builtin"], size);
  if (triangles <= kMaxCoarseTriangles) return;
  std::ostringstream s;
  s << "a coarse mesh size of this value would give about " << std::llround(triangles)
    << " coarse triangles, more than the limit of " << kMaxCoarseTriangles
    << "; use a larger size and more refinements";
  checker.error(size_pointer, s.str());
}

bool check_geo_file(const json& j, const std::string& pointer, RuleChecker& checker) {
  return check_local_file(j, pointer, checker, "gmsh .geo file");
}

bool check_msh_file(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!check_local_file(j, pointer, checker, "gmsh .msh file")) return false;
  const std::size_t max = checker.options().limits.max_text_bytes;
  const auto text = read_text_file(j.get<std::string>(), max);
  if (!text) {
    checker.error(pointer, "cannot read the file " + j.get<std::string>());
    return false;
  }
  if (text->size() > max) {
    checker.error(pointer, "the file is larger than the limit of " + std::to_string(max) +
                               " bytes for msh text");
    return false;
  }
  return check_msh_text(json(*text), pointer, checker);
}

}  // namespace

ValueRule geo_file_value(const CaseLimits& limits) {
  ValueRule r = string_value(limits.max_path_length, "the path");
  r.hook = check_geo_file;
  r.notes = "command line only; the file must exist";
  return r;
}

ValueRule msh_text_value(const CaseLimits& limits) {
  ValueRule r = string_value(limits.max_text_bytes, "the msh text");
  r.hook = check_msh_text;
  r.notes = "must start with $MeshFormat (gmsh ASCII format 4.1)";
  return r;
}

std::string read_msh_file(const std::string& path) {
  return read_text_file(path, CaseLimits{}.max_text_bytes).value_or("");
}

ValueRule msh_file_value(const CaseLimits& limits, const std::string& contents) {
  ValueRule r = string_value(limits.max_path_length, "the path");
  r.hook = check_msh_file;
  r.notes = "command line only; the file must exist and hold " + contents;
  return r;
}

namespace {

/// mesh.geometry: a 2D outline; refused in 3D with where a 3D mesh comes from.
FieldRule geometry_field(const CaseReadOptions& options, int dim) {
  if (dim == 3)
    return refused_field("geometry",
                         "geometry (points, lines and arcs meshed by gmsh) describes a 2D body; a "
                         "3D mesh comes from builtin, msh, msh_file or geo_file");
  return optional_field(
      "geometry", object_value(geometry_rule(options)), nullptr,
      std::string(dim == 0 ? "(2D) " : "") + "points, lines and arcs, meshed with gmsh");
}

/// Refinements in 2D, and in 3D, where each multiplies the unknowns by about 8, fewer.
FieldRule refinements_field(const CaseLimits& limits, int dim) {
  const int most = dim == 3 ? std::min(limits.max_refinements, limits.max_refinements_3d)
                            : limits.max_refinements;
  std::string meaning = "uniform refinements of the coarse mesh (" +
                        in_dimension(dim, "each triangle into 4", "each tetrahedron into 8", ", ") +
                        "); the multilevel hierarchy has refinements + 1 levels";
  if (dim == 0) meaning += "; at most " + std::to_string(limits.max_refinements_3d) + " in 3D";
  return optional_field("refinements", integer_value(Range::closed(0, most)),
                        MeshSpec{}.refinements, meaning);
}

}  // namespace

ObjectRulePtr mesh_rule(const CaseReadOptions& options, int dim) {
  const CaseLimits& limits = options.limits;
  const MeshSpec defaults;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the mesh";
  r->anchor = "mesh";
  const std::string of = dim == 2 ? "" : ": " + in_dimension(dim, "triangles", "tetrahedra");
  r->fields = {
      optional_field("builtin", builtin_value(dim), nullptr, builtin_meaning(dim)),
      geometry_field(options, dim),
      optional_field("msh", msh_text_value(limits), nullptr,
                     "the text of a gmsh mesh file (ASCII 4.1)" + of),
      optional_field("msh_file",
                     msh_file_value(limits, dim == 3 ? "msh text with tetrahedra" : "msh text"),
                     nullptr, "the path of a gmsh mesh file (ASCII 4.1)" + of + ", read like msh"),
      optional_field(
          "geo_file", geo_file_value(limits), nullptr,
          "the path of a gmsh .geo script" + std::string(dim == 3 ? ", meshed in 3D" : "")),
      optional_field("size", number_value(Range::positive()), defaults.size,
                     "target edge length of the coarse mesh (" +
                         in_dimension(dim, "not used by msh", "geo_file only") + ")"),
      refinements_field(limits, dim),
      optional_field("order", integer_value(Range::closed(1, 2)), defaults.order,
                     "polynomial order of the space on the finest mesh: 1 (P1 displacement × RT0 "
                     "stress rows) or 2 (P2 × RT1, solved by the multilevel method on the "
                     "order-1 levels of the same meshes" +
                         std::string(dim == 2 ? "" : "; 2D only for now") + ")"),
  };
  if (dim == 3)
    r->exclusive = {{{{"builtin"}, {"msh"}, {"msh_file"}, {"geo_file"}},
                     "no mesh source: give exactly one of builtin, msh, msh_file or geo_file",
                     "give exactly one mesh source, not {given}"}};
  else
    r->exclusive = {{{{"builtin"}, {"geometry"}, {"msh"}, {"msh_file"}, {"geo_file"}},
                     "no mesh source: give exactly one of builtin, geometry, msh, msh_file or "
                     "geo_file",
                     "give exactly one mesh source, not {given}"}};
  if (dim == 3) return r;
  r->hook = check_coarse_size;
  r->notes = std::string(dim == 0 ? "2D: " : "") +
             "a size whose coarse mesh would have more than the limit of coarse triangles is "
             "refused before meshing";
  return r;
}

MeshSpec read_mesh_section(const json& j) {
  MeshSpec m;
  m.size = j.value("size", m.size);
  m.refinements = j.value("refinements", m.refinements);
  m.order = j.value("order", m.order);
  if (const auto it = j.find("builtin"); it != j.end()) {
    read_builtin(*it, m);
  } else if (const auto it = j.find("geometry"); it != j.end()) {
    m.kind = MeshSpec::Kind::kGeometry;
    m.geometry = read_geometry_section(*it);
  } else if (const auto it = j.find("msh"); it != j.end()) {
    m.kind = MeshSpec::Kind::kMsh;
    m.msh_text = it->get<std::string>();
  } else if (const auto it = j.find("msh_file"); it != j.end()) {
    // Checked readable by its rule; read once more here, the text is the mesh.
    m.kind = MeshSpec::Kind::kMsh;
    m.msh_path = it->get<std::string>();
    m.msh_text = read_msh_file(m.msh_path);
  } else if (const auto it = j.find("geo_file"); it != j.end()) {
    m.kind = MeshSpec::Kind::kGeoFile;
    m.geo_path = it->get<std::string>();
  }
  return m;
}

}  // namespace fosls
