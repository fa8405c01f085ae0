#include "case/case_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <numbers>
#include <sstream>
#include <utility>

#include "case/expression.hpp"

namespace fosls {

namespace {

using nlohmann::json;

/// RFC 6901: "~" is written "~0" and "/" is written "~1" inside a reference token.
std::string escape_token(const std::string& key) {
  std::string out;
  out.reserve(key.size());
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string child(const std::string& pointer, const std::string& key) {
  return pointer + "/" + escape_token(key);
}

std::string child(const std::string& pointer, std::size_t index) {
  return pointer + "/" + std::to_string(index);
}

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

/// What a value is, for "expected …, got …" messages.
std::string describe_value(const json& j) {
  switch (j.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return std::string("the boolean ") + (j.get<bool>() ? "true" : "false");
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return "the number " + format_number(j.get<double>());
    case json::value_t::string: {
      const auto& s = j.get_ref<const std::string&>();
      if (s.size() > 40) return "a string of " + std::to_string(s.size()) + " characters";
      return "the string " + j.dump(-1, ' ', false, json::error_handler_t::replace);
    }
    case json::value_t::array:
      return "an array of " + std::to_string(j.size()) + " element" + (j.size() == 1 ? "" : "s");
    case json::value_t::object:
      return "an object";
    default:
      return "a value of an unsupported type";
  }
}

std::string join_names(std::initializer_list<const char*> names) {
  std::string s;
  for (const char* n : names) {
    if (!s.empty()) s += ", ";
    s += n;
  }
  return s;
}

/// Inclusive or exclusive bounds for a number, with the words for the message.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const {
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {
    const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
    if (has_lo && has_hi)
      return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " +
             format_number(hi) + (hi_open ? ")" : "]");
    if (has_lo) return std::string(lo_open ? "> " : ">= ") + format_number(lo);
    if (has_hi) return std::string(hi_open ? "< " : "<= ") + format_number(hi);
    return "finite";
  }
};

constexpr double kInf = std::numeric_limits<double>::infinity();
const Range kPositive{0.0, kInf, true, false};
const Range kNonNegative{0.0, kInf, false, false};
const Range kAny{};

/// Reads one case JSON into a CaseSpec, collecting every problem instead of stopping at the
/// first. Each reader method leaves the default in place when its field has an error, so the
/// rest of the case is still checked.
class CaseReader {
 public:
  explicit CaseReader(const CaseReadOptions& options) : options_(options) {}

  CaseReadResult read(const json& j) {
    CaseSpec spec;
    if (!j.is_object()) {
      error("", "the case must be a JSON object with the fields mesh, material and boundary, got " +
                    describe_value(j));
      return finish(std::move(spec));
    }
    check_fields(j, "", "the case",
                 {"name", "mesh", "material", "body_force", "boundary", "weights", "solver"});
    if (const json* v = field(j, "name"))
      if (auto s = read_name(*v, "/name")) spec.name = *s;
    if (const json* v = required(j, "", "mesh", "the mesh of the body"))
      read_mesh(*v, "/mesh", spec.mesh);
    if (const json* v = required(j, "", "material", "the material (mu and lambda, or E and nu)"))
      read_material(*v, "/material", spec.material);
    if (const json* v = field(j, "body_force"))
      if (auto f = read_scalar_pair(*v, "/body_force")) spec.body_force = *f;
    if (const json* v = required(j, "", "boundary", "the conditions on the boundary groups"))
      read_boundary(*v, "/boundary", spec.boundary);
    if (const json* v = field(j, "weights")) read_weights(*v, "/weights", spec.weights);
    if (const json* v = field(j, "solver")) read_solver(*v, "/solver", spec.solver);
    return finish(std::move(spec));
  }

 private:
  CaseReadResult finish(CaseSpec spec) {
    CaseReadResult result;
    if (errors_.empty()) result.spec = std::move(spec);
    result.errors = std::move(errors_);
    return result;
  }

  void error(std::string pointer, std::string detail) {
    errors_.push_back({std::move(pointer), std::move(detail)});
  }

  // ---- generic field access -------------------------------------------------------------

  static const json* field(const json& object, const char* key) {
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  const json* required(const json& object, const std::string& pointer, const char* key,
                       const std::string& what) {
    const json* v = field(object, key);
    if (!v) error(child(pointer, key), std::string("missing field \"") + key + "\": " + what);
    return v;
  }

  bool expect_object(const json& j, const std::string& pointer, const std::string& what) {
    if (j.is_object()) return true;
    error(pointer, "expected an object (" + what + "), got " + describe_value(j));
    return false;
  }

  /// Every key of `object` must be one of `allowed`.
  void check_fields(const json& object, const std::string& pointer, const std::string& what,
                    std::initializer_list<const char*> allowed) {
    for (const auto& [key, value] : object.items()) {
      const bool known = std::any_of(allowed.begin(), allowed.end(),
                                     [&key = key](const char* a) { return key == a; });
      if (!known)
        error(child(pointer, key), "unknown field \"" + key + "\" in " + what +
                                       ", expected one of: " + join_names(allowed));
    }
  }

  std::optional<double> read_number(const json& j, const std::string& pointer,
                                    const Range& range = kAny) {
    if (!j.is_number()) {
      error(pointer, "expected a number, got " + describe_value(j));
      return std::nullopt;
    }
    const double v = j.get<double>();
    if (!std::isfinite(v) || !range.contains(v)) {
      error(pointer, "must be " + range.text() + ", got " + format_number(v));
      return std::nullopt;
    }
    return v;
  }

  std::optional<int> read_int(const json& j, const std::string& pointer, int lo, int hi) {
    if (!j.is_number()) {
      error(pointer, "expected an integer, got " + describe_value(j));
      return std::nullopt;
    }
    const double v = j.get<double>();
    if (v != std::floor(v)) {
      error(pointer, "expected an integer, got " + format_number(v));
      return std::nullopt;
    }
    if (v < lo || v > hi) {
      error(pointer, "must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                         ", got " + format_number(v));
      return std::nullopt;
    }
    return static_cast<int>(v);
  }

  std::optional<std::string> read_string(const json& j, const std::string& pointer) {
    if (!j.is_string()) {
      error(pointer, "expected a string, got " + describe_value(j));
      return std::nullopt;
    }
    return j.get<std::string>();
  }

  /// A name (case name, group name): non-empty, bounded, printable.
  std::optional<std::string> check_name(const std::string& s, const std::string& pointer,
                                        const std::string& what) {
    if (s.empty()) {
      error(pointer, what + " is empty; give a non-empty name");
      return std::nullopt;
    }
    if (s.size() > options_.limits.max_name_length) {
      error(pointer, what + " is " + std::to_string(s.size()) + " characters long; at most " +
                         std::to_string(options_.limits.max_name_length) + " are allowed");
      return std::nullopt;
    }
    for (unsigned char c : s)
      if (c < 0x20 || c == 0x7f) {
        error(pointer, what + " contains a control character; use printable characters");
        return std::nullopt;
      }
    return s;
  }

  std::optional<std::string> read_name(const json& j, const std::string& pointer) {
    auto s = read_string(j, pointer);
    if (!s) return std::nullopt;
    return check_name(*s, pointer, "the name");
  }

  /// One of a fixed set of strings.
  template <class E>
  std::optional<E> read_choice(const json& j, const std::string& pointer,
                               std::initializer_list<std::pair<const char*, E>> choices) {
    std::string names;
    for (const auto& c : choices) names += std::string(names.empty() ? "" : ", ") + c.first;
    if (!j.is_string()) {
      error(pointer, "expected a string (one of " + names + "), got " + describe_value(j));
      return std::nullopt;
    }
    const auto& s = j.get_ref<const std::string&>();
    for (const auto& c : choices)
      if (s == c.first) return c.second;
    const std::string value =
        s.size() > 40 ? describe_value(j) : j.dump(-1, ' ', false, json::error_handler_t::replace);
    error(pointer, "unknown value " + value + ", expected one of: " + names);
    return std::nullopt;
  }

  /// A number or a muParser expression of x and y.
  std::optional<Scalar> read_scalar(const json& j, const std::string& pointer) {
    Scalar s;
    if (j.is_number()) {
      if (auto v = read_number(j, pointer)) {
        s.value = *v;
        return s;
      }
      return std::nullopt;
    }
    if (!j.is_string()) {
      error(pointer, "expected a number or a string with an expression of x and y, got " +
                         describe_value(j));
      return std::nullopt;
    }
    s.expression = j.get<std::string>();
    if (auto reason = check_expression(s.expression, options_.limits.max_expression_length)) {
      error(pointer, *reason);
      return std::nullopt;
    }
    return s;
  }

  bool expect_pair(const json& j, const std::string& pointer, const std::string& what) {
    if (j.is_array() && j.size() == 2) return true;
    error(pointer, "expected an array of 2 " + what + ", got " + describe_value(j));
    return false;
  }

  std::optional<std::array<Scalar, 2>> read_scalar_pair(const json& j, const std::string& pointer) {
    if (!expect_pair(j, pointer, "numbers or expressions of x and y")) return std::nullopt;
    auto a = read_scalar(j[0], child(pointer, 0));
    auto b = read_scalar(j[1], child(pointer, 1));
    if (!a || !b) return std::nullopt;
    return std::array<Scalar, 2>{*a, *b};
  }

  std::optional<Point> read_point(const json& j, const std::string& pointer) {
    if (!expect_pair(j, pointer, "numbers [x, y]")) return std::nullopt;
    auto a = read_number(j[0], child(pointer, 0));
    auto b = read_number(j[1], child(pointer, 1));
    if (!a || !b) return std::nullopt;
    return Point(*a, *b);
  }

  /// A number field with a default: the default stays when the field is absent or wrong.
  void read_optional_number(const json& object, const std::string& pointer, const char* key,
                            const Range& range, double& target) {
    if (const json* v = field(object, key))
      if (auto x = read_number(*v, child(pointer, key), range)) target = *x;
  }

  // ---- mesh -----------------------------------------------------------------------------

  void read_mesh(const json& j, const std::string& pointer, MeshSpec& mesh) {
    if (!expect_object(j, pointer,
                       "the mesh: one of builtin, geometry, msh, geo_file, plus "
                       "size and refinements"))
      return;
    check_fields(j, pointer, "the mesh",
                 {"builtin", "geometry", "msh", "geo_file", "size", "refinements"});
    read_optional_number(j, pointer, "size", kPositive, mesh.size);
    if (const json* v = field(j, "refinements"))
      if (auto r = read_int(*v, child(pointer, "refinements"), 0, options_.limits.max_refinements))
        mesh.refinements = *r;

    std::vector<const char*> sources;
    for (const char* key : {"builtin", "geometry", "msh", "geo_file"})
      if (field(j, key)) sources.push_back(key);
    if (sources.empty()) {
      error(pointer, "no mesh source: give exactly one of builtin, geometry, msh or geo_file");
      return;
    }
    if (sources.size() > 1) {
      std::string list;
      for (std::size_t i = 0; i < sources.size(); ++i)
        list += std::string(i == 0 ? "" : (i + 1 == sources.size() ? " and " : ", ")) + sources[i];
      error(pointer, "give exactly one mesh source, not " + list);
    }
    // Every given source is checked, so that all of its problems show at once.
    if (const json* v = field(j, "builtin")) {
      mesh.kind = MeshSpec::Kind::kBuiltin;
      read_builtin(*v, child(pointer, "builtin"), mesh);
    }
    if (const json* v = field(j, "geometry")) {
      mesh.kind = MeshSpec::Kind::kGeometry;
      read_geometry(*v, child(pointer, "geometry"), mesh);
    }
    if (const json* v = field(j, "msh")) {
      mesh.kind = MeshSpec::Kind::kMsh;
      read_msh(*v, child(pointer, "msh"), mesh);
    }
    if (const json* v = field(j, "geo_file")) {
      mesh.kind = MeshSpec::Kind::kGeoFile;
      read_geo_file(*v, child(pointer, "geo_file"), mesh);
    }
  }

  void check_coarse_size(const std::string& pointer, double triangles) {
    if (triangles <= static_cast<double>(options_.limits.max_coarse_triangles)) return;
    std::ostringstream s;
    s << "a coarse mesh size of this value would give about " << std::llround(triangles)
      << " coarse triangles, more than the limit of " << options_.limits.max_coarse_triangles
      << "; use a larger size and more refinements";
    error(pointer, s.str());
  }

  void read_builtin(const json& j, const std::string& pointer, MeshSpec& mesh) {
    std::string name_pointer = pointer;
    const json* name = &j;
    if (j.is_object()) {
      name_pointer = child(pointer, "name");
      name = required(j, pointer, "name", "the builtin geometry, square or hertz");
      if (!name) return;
    } else if (!j.is_string()) {
      error(pointer,
            "expected the name of a builtin geometry (\"square\" or \"hertz\") or an object "
            "{\"name\": ..., parameters}, got " +
                describe_value(*name));
      return;
    }
    enum class Builtin { kSquare, kHertz };
    auto kind = read_choice<Builtin>(*name, name_pointer,
                                     {{"square", Builtin::kSquare}, {"hertz", Builtin::kHertz}});
    if (!kind) return;
    // All parameters are stored, defaults included, so the mesh builder needs no defaults.
    auto& p = mesh.params;
    if (*kind == Builtin::kSquare) {
      mesh.builtin = "square";
      p = {{"x0", 0.0}, {"y0", 0.0}, {"width", 1.0}, {"height", 1.0}};
      if (j.is_object()) {
        check_fields(j, pointer, "the square", {"name", "x0", "y0", "width", "height"});
        read_optional_number(j, pointer, "x0", kAny, p["x0"]);
        read_optional_number(j, pointer, "y0", kAny, p["y0"]);
        read_optional_number(j, pointer, "width", kPositive, p["width"]);
        read_optional_number(j, pointer, "height", kPositive, p["height"]);
      }
      const double nx = std::max(1.0, std::ceil(p["width"] / mesh.size));
      const double ny = std::max(1.0, std::ceil(p["height"] / mesh.size));
      check_coarse_size("/mesh/size", 2.0 * nx * ny);
    } else {
      mesh.builtin = "hertz";
      p = {{"radius", 1.0}, {"contact_fraction", 0.5}, {"grading", 7.0}};
      if (j.is_object()) {
        check_fields(j, pointer, "the hertz geometry",
                     {"name", "radius", "contact_fraction", "grading"});
        read_optional_number(j, pointer, "radius", kPositive, p["radius"]);
        read_optional_number(j, pointer, "contact_fraction", Range{0.0, 1.0, true, true},
                             p["contact_fraction"]);
        read_optional_number(j, pointer, "grading", Range{1.0, 100.0, false, false}, p["grading"]);
      }
      // Ungraded estimate (an upper bound): half disk area / area of a triangle of edge size.
      const double area = 0.5 * std::numbers::pi * p["radius"] * p["radius"];
      check_coarse_size("/mesh/size", area / (0.433 * mesh.size * mesh.size));
    }
  }

  void read_geometry(const json& j, const std::string& pointer, MeshSpec& mesh) {
    if (!expect_object(j, pointer, "points, curves and groups")) return;
    check_fields(j, pointer, "the geometry", {"points", "curves", "groups"});
    GeometrySpec& g = mesh.geometry;
    const std::size_t max_entities = options_.limits.max_geometry_entities;
    auto array_field = [&](const char* key, const std::string& what) -> const json* {
      const json* v = required(j, pointer, key, what);
      if (!v) return nullptr;
      const std::string p = child(pointer, key);
      if (!v->is_array() || v->empty()) {
        error(p, "expected a non-empty array (" + what + "), got " + describe_value(*v));
        return nullptr;
      }
      if (v->size() > max_entities) {
        error(p, "has " + std::to_string(v->size()) + " entries; at most " +
                     std::to_string(max_entities) + " are allowed");
        return nullptr;
      }
      return v;
    };

    bool points_ok = true;
    if (const json* points = array_field("points", "the points [x, y] of the geometry")) {
      for (std::size_t i = 0; i < points->size(); ++i) {
        auto p = read_point((*points)[i], child(child(pointer, "points"), i));
        points_ok = points_ok && p.has_value();
        g.points.push_back(p.value_or(Point::Zero()));
      }
    } else {
      points_ok = false;
    }

    bool curves_ok = true;
    const std::string curves_pointer = child(pointer, "curves");
    if (const json* curves = array_field("curves", "lines and arcs forming one closed loop")) {
      for (std::size_t k = 0; k < curves->size(); ++k) {
        auto c = read_curve((*curves)[k], child(curves_pointer, k), g.points.size(), points_ok,
                            g.points);
        curves_ok = curves_ok && c.has_value();
        g.curves.push_back(c.value_or(GeometrySpec::Curve{}));
      }
    } else {
      curves_ok = false;
    }

    bool groups_ok = true;
    const std::string groups_pointer = child(pointer, "groups");
    std::vector<std::vector<std::string>> groups_of_curve(g.curves.size());
    if (const json* groups = required(j, pointer, "groups", "named lists of curve indices")) {
      if (!groups->is_object() || groups->empty()) {
        error(groups_pointer,
              "expected a non-empty object mapping each boundary group name to a list of curve "
              "indices, got " +
                  describe_value(*groups));
        groups_ok = false;
      } else if (groups->size() > max_entities) {
        error(groups_pointer, "has " + std::to_string(groups->size()) + " groups; at most " +
                                  std::to_string(max_entities) + " are allowed");
        groups_ok = false;
      } else {
        for (const auto& [name, list] : groups->items()) {
          const std::string gp = child(groups_pointer, name);
          GeometrySpec::Group group;
          if (auto n = check_name(name, gp, "the group name"))
            group.name = *n;
          else
            groups_ok = false;
          if (!list.is_array() || list.empty()) {
            error(gp, "expected a non-empty array of curve indices, got " + describe_value(list));
            groups_ok = false;
            continue;
          }
          if (list.size() > max_entities) {
            error(gp, "has " + std::to_string(list.size()) + " entries; at most " +
                          std::to_string(max_entities) + " are allowed");
            groups_ok = false;
            continue;
          }
          for (std::size_t i = 0; i < list.size(); ++i) {
            auto index = read_index(list[i], child(gp, i), g.curves.size());
            if (!index) {
              groups_ok = false;
              continue;
            }
            auto& owners = groups_of_curve[*index];
            if (!owners.empty() && owners.back() == name) {
              error(child(gp, i), "curve " + std::to_string(*index) +
                                      " is listed twice in this group; list it once");
              groups_ok = false;
              continue;
            }
            group.curves.push_back(*index);
            owners.push_back(name);
          }
          g.groups.push_back(std::move(group));
        }
      }
    } else {
      groups_ok = false;
    }

    if (curves_ok && groups_ok) {
      for (std::size_t k = 0; k < groups_of_curve.size(); ++k) {
        const auto& names = groups_of_curve[k];
        if (names.empty())
          error(child(curves_pointer, k),
                "curve " + std::to_string(k) +
                    " is in no boundary group; list it in exactly one group of " + groups_pointer);
        else if (names.size() > 1)
          error(child(curves_pointer, k), "curve " + std::to_string(k) + " is in " +
                                              std::to_string(names.size()) + " groups (\"" +
                                              names[0] + "\" and \"" + names[1] +
                                              "\"); list it in exactly one group");
      }
    }
    if (points_ok && curves_ok) {
      check_closed_loop(g, curves_pointer);
      check_coarse_size("/mesh/size", geometry_area_bound(g) / (0.433 * mesh.size * mesh.size));
    }
  }

  /// An index into a list of `count` entries; nothing more is reported when the list itself
  /// is missing (its own error says so).
  std::optional<int> read_index(const json& j, const std::string& pointer, std::size_t count) {
    if (count == 0) return std::nullopt;
    return read_int(j, pointer, 0, static_cast<int>(count) - 1);
  }

  std::optional<GeometrySpec::Curve> read_curve(const json& j, const std::string& pointer,
                                                std::size_t num_points, bool points_ok,
                                                const std::vector<Point>& points) {
    if (!expect_object(j, pointer, "{\"type\": \"line\" or \"arc\", \"points\": [i, j]}"))
      return std::nullopt;
    const json* type = required(j, pointer, "type", "\"line\" or \"arc\"");
    if (!type) return std::nullopt;
    auto is_arc =
        read_choice<bool>(*type, child(pointer, "type"), {{"line", false}, {"arc", true}});
    if (!is_arc) return std::nullopt;
    GeometrySpec::Curve c;
    c.is_arc = *is_arc;
    if (c.is_arc)
      check_fields(j, pointer, "an arc", {"type", "points", "center"});
    else
      check_fields(j, pointer, "a line", {"type", "points"});
    bool ok = true;
    if (const json* ends = required(j, pointer, "points", "the indices [i, j] of its end points")) {
      const std::string ep = child(pointer, "points");
      if (!expect_pair(*ends, ep, "point indices")) {
        ok = false;
      } else {
        for (std::size_t e = 0; e < 2; ++e) {
          auto index = read_index((*ends)[e], child(ep, e), num_points);
          if (index)
            c.points[e] = *index;
          else
            ok = false;
        }
        if (ok && c.points[0] == c.points[1]) {
          error(ep, "the curve starts and ends at the same point; use two different points");
          ok = false;
        }
      }
    } else {
      ok = false;
    }
    if (c.is_arc) {
      if (const json* center =
              required(j, pointer, "center", "the index of the arc's centre point")) {
        if (auto index = read_index(*center, child(pointer, "center"), num_points))
          c.center = *index;
        else
          ok = false;
      } else {
        ok = false;
      }
    }
    if (!ok || !points_ok) return ok ? std::optional(c) : std::nullopt;

    const Point& a = points[c.points[0]];
    const Point& b = points[c.points[1]];
    if ((a - b).norm() == 0.0) {
      error(child(pointer, "points"), "the curve has zero length: its end points coincide");
      return std::nullopt;
    }
    if (c.is_arc) {
      const Point& m = points[c.center];
      const double ra = (a - m).norm(), rb = (b - m).norm();
      if (ra == 0.0 || rb == 0.0) {
        error(child(pointer, "center"), "the centre coincides with an end point of the arc");
        return std::nullopt;
      }
      if (std::abs(ra - rb) > 1e-9 * std::max(ra, rb)) {  // as the gmsh mesher checks
        error(child(pointer, "center"),
              "the end points are not equidistant from the centre (distances " + format_number(ra) +
                  " and " + format_number(rb) + "); an arc is part of a circle around the centre");
        return std::nullopt;
      }
      // A half circle has two "shorter ways"; gmsh would pick one arbitrarily.
      if ((a - m + (b - m)).norm() < 1e-9 * ra) {
        error(pointer, "the arc is a half circle, which is ambiguous; split it into two arcs");
        return std::nullopt;
      }
    }
    return c;
  }

  /// The curves must form one closed loop: every end point shared by exactly two curves,
  /// and all curves connected.
  void check_closed_loop(const GeometrySpec& g, const std::string& curves_pointer) {
    std::vector<int> degree(g.points.size(), 0);
    std::vector<int> parent(g.points.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
    auto find = [&](int i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    for (const auto& c : g.curves) {
      ++degree[c.points[0]];
      ++degree[c.points[1]];
      parent[find(c.points[0])] = find(c.points[1]);
    }
    bool degrees_ok = true;
    for (std::size_t i = 0; i < degree.size(); ++i)
      if (degree[i] != 0 && degree[i] != 2) {
        error(curves_pointer, "point " + std::to_string(i) + " is an end of " +
                                  std::to_string(degree[i]) +
                                  " curves; the curves must form one closed loop, so every end "
                                  "point belongs to exactly two curves");
        degrees_ok = false;
      }
    if (!degrees_ok) return;
    int loops = 0;
    for (std::size_t i = 0; i < degree.size(); ++i)
      if (degree[i] != 0 && find(static_cast<int>(i)) == static_cast<int>(i)) ++loops;
    if (loops > 1)
      error(curves_pointer, "the curves form " + std::to_string(loops) +
                                " separate loops; give one closed loop (holes are not supported)");
  }

  /// Area of the bounding box of the geometry (arcs contribute their whole circle).
  static double geometry_area_bound(const GeometrySpec& g) {
    Point lo = Point::Constant(kInf), hi = Point::Constant(-kInf);
    auto add = [&](const Point& p) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    };
    for (const auto& c : g.curves) {
      add(g.points[c.points[0]]);
      add(g.points[c.points[1]]);
      if (c.is_arc) {
        const Point& m = g.points[c.center];
        const double r = (g.points[c.points[0]] - m).norm();
        add(m - Point(r, r));
        add(m + Point(r, r));
      }
    }
    if (!(hi.x() >= lo.x())) return 0.0;
    return (hi - lo).prod();
  }

  void read_msh(const json& j, const std::string& pointer, MeshSpec& mesh) {
    auto text = read_string(j, pointer);
    if (!text) return;
    if (text->size() > options_.limits.max_text_bytes) {
      error(pointer, "the msh text has " + std::to_string(text->size()) + " bytes; at most " +
                         std::to_string(options_.limits.max_text_bytes) + " are allowed");
      return;
    }
    const auto start = text->find_first_not_of(" \t\r\n");
    if (start == std::string::npos) {
      error(pointer, "the msh text is empty; give the contents of a gmsh .msh file");
      return;
    }
    if (text->compare(start, 11, "$MeshFormat") != 0) {
      error(pointer,
            "this is not gmsh .msh text: it must start with $MeshFormat (save the mesh from "
            "gmsh in ASCII format 4.1)");
      return;
    }
    mesh.msh_text = std::move(*text);
  }

  void read_geo_file(const json& j, const std::string& pointer, MeshSpec& mesh) {
    if (!options_.allow_geo_file) {
      error(pointer,
            "a .geo file is accepted only by the command line program (fosls-contact solve), "
            "because gmsh scripts can run shell commands; use mesh.geometry or mesh.msh "
            "instead");
      return;
    }
    auto path = read_string(j, pointer);
    if (!path) return;
    if (path->empty()) {
      error(pointer, "the path is empty; give the path of a gmsh .geo file");
      return;
    }
    if (path->size() > options_.limits.max_path_length) {
      error(pointer, "the path is " + std::to_string(path->size()) + " characters long; at most " +
                         std::to_string(options_.limits.max_path_length) + " are allowed");
      return;
    }
    if (path->find('\0') != std::string::npos) {
      error(pointer, "the path contains a NUL character");
      return;
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(*path, ec)) {
      error(pointer, "no such file: " + *path +
                         " (a relative path is taken relative to the case file's folder)");
      return;
    }
    mesh.geo_path = std::move(*path);
  }

  // ---- material -------------------------------------------------------------------------

  void read_material(const json& j, const std::string& pointer, Material& m) {
    if (!expect_object(j, pointer, "mu and lambda, or E and nu")) return;
    check_fields(j, pointer, "the material", {"mu", "lambda", "E", "nu"});
    const bool lame = field(j, "mu") || field(j, "lambda");
    const bool young = field(j, "E") || field(j, "nu");
    if (lame && young) {
      error(pointer, "give either mu and lambda, or E and nu, not both");
      return;
    }
    if (!lame && !young) {
      error(pointer, "missing material parameters: give mu and lambda, or E and nu");
      return;
    }
    if (lame) {
      std::optional<double> mu, lambda;
      if (const json* v = required(j, pointer, "mu", "the shear modulus (> 0)"))
        mu = read_number(*v, child(pointer, "mu"), kPositive);
      if (const json* v =
              required(j, pointer, "lambda", "the Lame parameter lambda (>= 0, or \"inf\")"))
        lambda = read_lambda(*v, child(pointer, "lambda"));
      if (mu && lambda) {
        m.mu = *mu;
        m.lambda = *lambda;
      }
      return;
    }
    std::optional<double> E, nu;
    if (const json* v = required(j, pointer, "E", "Young's modulus (> 0)"))
      E = read_number(*v, child(pointer, "E"), kPositive);
    if (const json* v = required(j, pointer, "nu", "Poisson's ratio in (-1, 0.5]"))
      nu = read_number(*v, child(pointer, "nu"), Range{-1.0, 0.5, true, false});
    if (E && nu) {
      m.mu = *E / (2.0 * (1.0 + *nu));
      m.lambda = *nu == 0.5 ? kInf : *E * *nu / ((1.0 + *nu) * (1.0 - 2.0 * *nu));
    }
  }

  std::optional<double> read_lambda(const json& j, const std::string& pointer) {
    if (j.is_string()) {
      if (j.get_ref<const std::string&>() == "inf") return kInf;
      error(pointer, "expected a number >= 0 or the string \"inf\" (incompressible), got " +
                         describe_value(j));
      return std::nullopt;
    }
    if (!j.is_number()) {
      error(pointer, "expected a number >= 0 or the string \"inf\" (incompressible), got " +
                         describe_value(j));
      return std::nullopt;
    }
    const double v = j.get<double>();
    if (std::isfinite(v) && v < 0) {
      error(pointer, "lambda is negative (" + format_number(v) +
                         "); it must be >= 0, or \"inf\" for an incompressible material");
      return std::nullopt;
    }
    return read_number(j, pointer, kNonNegative);
  }

  // ---- boundary -------------------------------------------------------------------------

  void read_boundary(const json& j, const std::string& pointer,
                     std::map<std::string, BoundaryCondition>& boundary) {
    if (!j.is_object() || j.empty()) {
      error(pointer,
            "expected a non-empty object mapping boundary group names to conditions, got " +
                describe_value(j));
      return;
    }
    if (j.size() > options_.limits.max_geometry_entities) {
      error(pointer, "has " + std::to_string(j.size()) + " conditions; at most " +
                         std::to_string(options_.limits.max_geometry_entities) + " are allowed");
      return;
    }
    for (const auto& [name, value] : j.items()) {
      const std::string p = child(pointer, name);
      auto n = check_name(name, p, "the boundary group name");
      auto bc = read_condition(value, p);
      if (n && bc) boundary[*n] = *bc;
    }
  }

  std::optional<BoundaryCondition> read_condition(const json& j, const std::string& pointer) {
    if (!expect_object(j, pointer, "a condition with \"type\": dirichlet, neumann or contact"))
      return std::nullopt;
    const json* type = required(j, pointer, "type", "dirichlet, neumann or contact");
    if (!type) return std::nullopt;
    using Type = BoundaryCondition::Type;
    auto t = read_choice<Type>(*type, child(pointer, "type"),
                               {{"dirichlet", Type::kDirichlet},
                                {"neumann", Type::kNeumann},
                                {"contact", Type::kContact}});
    if (!t) return std::nullopt;
    BoundaryCondition bc;
    bc.type = *t;
    bool ok = true;
    auto pair = [&](const char* key, const std::string& what) {
      const json* v = required(j, pointer, key, what);
      auto values = v ? read_scalar_pair(*v, child(pointer, key)) : std::nullopt;
      if (values)
        bc.values = *values;
      else
        ok = false;
    };
    switch (*t) {
      case Type::kDirichlet:
        check_fields(j, pointer, "a dirichlet condition", {"type", "displacement"});
        pair("displacement", "the prescribed displacement [u_x, u_y]");
        break;
      case Type::kNeumann:
        check_fields(j, pointer, "a neumann condition", {"type", "traction"});
        pair("traction", "the prescribed traction [t_x, t_y]");
        break;
      case Type::kContact: {
        check_fields(j, pointer, "a contact condition", {"type", "obstacle", "direction"});
        if (const json* v = required(j, pointer, "obstacle", "a plane, circle or gap"))
          ok = read_obstacle(*v, child(pointer, "obstacle"), bc.obstacle) && ok;
        else
          ok = false;
        if (const json* v = field(j, "direction")) {
          const std::string dp = child(pointer, "direction");
          auto d = read_choice<ContactDirection>(
              *v, dp,
              {{"body_normal", ContactDirection::kBodyNormal},
               {"obstacle_normal", ContactDirection::kObstacleNormal}});
          if (!d) {
            ok = false;
          } else if (*d == ContactDirection::kObstacleNormal && ok &&
                     bc.obstacle.kind == Obstacle::Kind::kGap) {
            error(dp,
                  "direction obstacle_normal needs a plane or circle obstacle; a gap obstacle "
                  "has no normal of its own (use body_normal)");
            ok = false;
          } else {
            bc.direction = *d;
          }
        }
        break;
      }
    }
    return ok ? std::optional(bc) : std::nullopt;
  }

  bool read_obstacle(const json& j, const std::string& pointer, Obstacle& o) {
    if (!expect_object(j, pointer, "an obstacle with \"type\": plane, circle or gap")) return false;
    const json* type = required(j, pointer, "type", "plane, circle or gap");
    if (!type) return false;
    using Kind = Obstacle::Kind;
    auto kind = read_choice<Kind>(
        *type, child(pointer, "type"),
        {{"plane", Kind::kPlane}, {"circle", Kind::kCircle}, {"gap", Kind::kGap}});
    if (!kind) return false;
    o.kind = *kind;
    bool ok = true;
    switch (*kind) {
      case Kind::kPlane: {
        check_fields(j, pointer, "a plane obstacle", {"type", "point", "normal"});
        if (const json* v = required(j, pointer, "point", "a point [x, y] on the plane")) {
          auto p = read_point(*v, child(pointer, "point"));
          ok = p.has_value() && ok;
          if (p) o.point = *p;
        } else {
          ok = false;
        }
        if (const json* v = required(j, pointer, "normal",
                                     "the normal [nx, ny] from the obstacle into the body")) {
          auto n = read_point(*v, child(pointer, "normal"));
          if (n && n->norm() == 0.0) {
            error(child(pointer, "normal"), "the normal is zero; give a non-zero vector");
            n.reset();
          }
          ok = n.has_value() && ok;
          if (n) o.normal = n->normalized();
        } else {
          ok = false;
        }
        break;
      }
      case Kind::kCircle: {
        check_fields(j, pointer, "a circle obstacle", {"type", "center", "radius"});
        if (const json* v = required(j, pointer, "center", "the centre [x, y] of the circle")) {
          auto c = read_point(*v, child(pointer, "center"));
          ok = c.has_value() && ok;
          if (c) o.center = *c;
        } else {
          ok = false;
        }
        if (const json* v = required(j, pointer, "radius", "the radius of the circle (> 0)")) {
          auto r = read_number(*v, child(pointer, "radius"), kPositive);
          ok = r.has_value() && ok;
          if (r) o.radius = *r;
        } else {
          ok = false;
        }
        break;
      }
      case Kind::kGap: {
        check_fields(j, pointer, "a gap obstacle", {"type", "g"});
        if (const json* v = required(j, pointer, "g",
                                     "the gap g(x, y): a number or an expression of x and y")) {
          auto g = read_scalar(*v, child(pointer, "g"));
          ok = g.has_value() && ok;
          if (g) o.gap = *g;
        } else {
          ok = false;
        }
        break;
      }
    }
    return ok;
  }

  // ---- weights and solver ---------------------------------------------------------------

  void read_weights(const json& j, const std::string& pointer, Weights& w) {
    if (!expect_object(j, pointer, "c1, c2, c3, c4")) return;
    check_fields(j, pointer, "the weights", {"c1", "c2", "c3", "c4"});
    read_optional_number(j, pointer, "c1", kPositive, w.c1);
    read_optional_number(j, pointer, "c2", kPositive, w.c2);
    read_optional_number(j, pointer, "c3", kNonNegative, w.c3);
    read_optional_number(j, pointer, "c4", kNonNegative, w.c4);
  }

  void read_solver(const json& j, const std::string& pointer, SolverSettings& s) {
    if (!expect_object(j, pointer, "the solver settings")) return;
    check_fields(j, pointer, "the solver settings",
                 {"method", "tolerance", "max_iterations", "smoother", "pre_smoothing",
                  "post_smoothing", "coarse_obstacle"});
    if (const json* v = field(j, "method"))
      if (auto m = read_choice<Method>(*v, child(pointer, "method"),
                                       {{"mmg", Method::kMmg},
                                        {"tnnmg", Method::kTnnmg},
                                        {"pdas", Method::kPdas},
                                        {"pgs", Method::kPgs}}))
        s.method = *m;
    read_optional_number(j, pointer, "tolerance", Range{0.0, 1.0, true, true}, s.tolerance);
    if (const json* v = field(j, "max_iterations"))
      if (auto n = read_int(*v, child(pointer, "max_iterations"), 1, 100000)) s.max_iterations = *n;
    if (const json* v = field(j, "smoother"))
      if (auto k = read_choice<SmootherKind>(
              *v, child(pointer, "smoother"),
              {{"patch", SmootherKind::kPatch}, {"point", SmootherKind::kPoint}}))
        s.smoother = *k;
    bool smoothing_ok = true;
    for (auto [key, target] : {std::pair{"pre_smoothing", &s.pre_smoothing},
                               std::pair{"post_smoothing", &s.post_smoothing}})
      if (const json* v = field(j, key)) {
        if (auto n = read_int(*v, child(pointer, key), 0, 10))
          *target = *n;
        else
          smoothing_ok = false;
      }
    if (smoothing_ok && s.method == Method::kMmg && s.pre_smoothing == 0 && s.post_smoothing == 0)
      error(child(pointer, "pre_smoothing"),
            "pre_smoothing and post_smoothing are both 0; the mmg method needs at least one "
            "smoothing step per level");
    if (const json* v = field(j, "coarse_obstacle"))
      if (auto c = read_choice<CoarseObstacle>(
              *v, child(pointer, "coarse_obstacle"),
              {{"a", CoarseObstacle::kA}, {"b", CoarseObstacle::kB}, {"c", CoarseObstacle::kC}}))
        s.coarse_obstacle = *c;
  }

  const CaseReadOptions& options_;
  std::vector<CaseError> errors_;
};

}  // namespace

CaseReadResult read_case(const nlohmann::json& j, const CaseReadOptions& options) {
  return CaseReader(options).read(j);
}

}  // namespace fosls
