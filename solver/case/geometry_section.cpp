// The `mesh.geometry` section: points, lines and arcs forming one closed loop, and the named
// boundary groups of its curves.

#include <algorithm>
#include <cmath>
#include <limits>

#include "case/case_sections.hpp"
#include "case/rule_checker.hpp"

namespace fosls {

namespace {

using nlohmann::json;

ObjectRulePtr curve_rule() {
  auto r = std::make_shared<ObjectRule>();
  r->title = "a curve";
  r->anchor = "curve";
  r->discriminator = "type";
  r->discriminator_meaning = "\"line\" or \"arc\"";
  const ValueRule index = integer_value(Range::non_negative());
  const ValueRule ends = tuple_value(index, 2, "an array of 2 point indices");
  r->variants = {
      {"line",
       "a line",
       "the segment from point i to point j",
       {required_field("points", ends, "the indices [i, j] of its end points")},
       {},
       ""},
      {"arc",
       "an arc",
       "the circular arc from point i to point j around point k, the shorter way",
       {required_field("points", ends, "the indices [i, j] of its end points"),
        required_field("center", index, "the index k of the arc's centre point")},
       {},
       ""},
  };
  return r;
}

/// Checks what needs more than one field: indices within their lists, the shape of each
/// curve, group membership and the closed loop. Uses only the parts that passed their rules.
class GeometryChecks {
 public:
  GeometryChecks(const json& j, const std::string& pointer, RuleChecker& checker)
      : j_(j), pointer_(pointer), checker_(checker) {}

  void run() {
    const std::string points_ptr = child_pointer(pointer_, "points");
    const std::string curves_ptr = child_pointer(pointer_, "curves");
    const std::string groups_ptr = child_pointer(pointer_, "groups");
    const bool points_ok = checker_.passed(points_ptr);
    const json* points = array_at("points");
    const json* curves = array_at("curves");
    bool curves_ok = checker_.passed(curves_ptr);
    if (points_ok) g_.points = read_geometry_section(json{{"points", *points}}).points;
    if (curves) {
      for (std::size_t k = 0; k < curves->size(); ++k) {
        const std::string cp = child_pointer(curves_ptr, k);
        if (!checker_.passed(cp)) continue;
        curves_ok =
            check_curve((*curves)[k], cp, points ? points->size() : 0, points_ok) && curves_ok;
      }
    }
    const bool groups_ok =
        checker_.passed(groups_ptr) && check_groups(j_["groups"], groups_ptr, curves);
    if (curves_ok && groups_ok) check_every_curve_in_one_group(curves_ptr, groups_ptr);
    if (points_ok && curves_ok) check_closed_loop(curves_ptr);
  }

 private:
  const json* array_at(const char* key) const {
    auto it = j_.find(key);
    return it != j_.end() && it->is_array() ? &*it : nullptr;
  }

  /// An index into a list of `count` entries; nothing is reported when the list itself is
  /// missing or empty (its own error says so).
  bool check_index(const json& index, const std::string& pointer, std::size_t count) {
    if (count == 0) return false;
    return checker_.check(index, integer_value(Range::closed(0, static_cast<double>(count) - 1)),
                          pointer);
  }

  bool check_curve(const json& c, const std::string& pointer, std::size_t num_points,
                   bool points_ok) {
    bool ok = true;
    const std::string ends_ptr = child_pointer(pointer, "points");
    for (std::size_t e = 0; e < 2; ++e)
      ok = check_index(c["points"][e], child_pointer(ends_ptr, e), num_points) && ok;
    const bool arc = c["type"] == "arc";
    if (arc) ok = check_index(c["center"], child_pointer(pointer, "center"), num_points) && ok;
    if (!ok) return false;
    const int ia = c["points"][0], ib = c["points"][1];
    if (ia == ib) {
      checker_.error(ends_ptr,
                     "the curve starts and ends at the same point; use two different points");
      return false;
    }
    if (!points_ok) return true;
    const Point& a = g_.points[ia];
    const Point& b = g_.points[ib];
    if ((a - b).norm() == 0.0) {
      checker_.error(ends_ptr, "the curve has zero length: its end points coincide");
      return false;
    }
    if (!arc) return true;
    const std::string center_ptr = child_pointer(pointer, "center");
    const Point& m = g_.points[c["center"].get<int>()];
    const double ra = (a - m).norm(), rb = (b - m).norm();
    if (ra == 0.0 || rb == 0.0) {
      checker_.error(center_ptr, "the centre coincides with an end point of the arc");
      return false;
    }
    if (std::abs(ra - rb) > 1e-9 * std::max(ra, rb)) {  // as the gmsh mesher checks
      checker_.error(center_ptr, "the end points are not equidistant from the centre (distances " +
                                     format_number(ra) + " and " + format_number(rb) +
                                     "); an arc is part of a circle around the centre");
      return false;
    }
    // A half circle has two "shorter ways"; gmsh would pick one arbitrarily.
    if ((a - m + (b - m)).norm() < 1e-9 * ra) {
      checker_.error(pointer,
                     "the arc is a half circle, which is ambiguous; split it into two arcs");
      return false;
    }
    return true;
  }

  bool check_groups(const json& groups, const std::string& pointer, const json* curves) {
    const std::size_t num_curves = curves ? curves->size() : 0;
    groups_of_curve_.assign(num_curves, {});
    bool ok = true;
    for (const auto& [name, list] : groups.items()) {
      const std::string gp = child_pointer(pointer, name);
      for (std::size_t i = 0; i < list.size(); ++i) {
        if (!check_index(list[i], child_pointer(gp, i), num_curves)) {
          ok = false;
          continue;
        }
        const int k = list[i];
        auto& owners = groups_of_curve_[k];
        if (!owners.empty() && owners.back() == name) {
          checker_.error(child_pointer(gp, i), "curve " + std::to_string(k) +
                                                   " is listed twice in this group; list it once");
          ok = false;
          continue;
        }
        owners.push_back(name);
      }
    }
    return ok && num_curves > 0;
  }

  void check_every_curve_in_one_group(const std::string& curves_ptr,
                                      const std::string& groups_ptr) {
    for (std::size_t k = 0; k < groups_of_curve_.size(); ++k) {
      const auto& names = groups_of_curve_[k];
      if (names.empty())
        checker_.error(child_pointer(curves_ptr, k),
                       "curve " + std::to_string(k) +
                           " is in no boundary group; list it in exactly one group of " +
                           groups_ptr);
      else if (names.size() > 1)
        checker_.error(child_pointer(curves_ptr, k),
                       "curve " + std::to_string(k) + " is in " + std::to_string(names.size()) +
                           " groups (\"" + names[0] + "\" and \"" + names[1] +
                           "\"); list it in exactly one group");
    }
  }

  /// Every end point shared by exactly two curves, and all curves connected.
  void check_closed_loop(const std::string& curves_ptr) {
    const GeometrySpec g = read_geometry_section(
        json{{"points", j_["points"]}, {"curves", j_["curves"]}, {"groups", json::object()}});
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
        checker_.error(curves_ptr, "point " + std::to_string(i) + " is an end of " +
                                       std::to_string(degree[i]) +
                                       " curves; the curves must form one closed loop, so every "
                                       "end point belongs to exactly two curves");
        degrees_ok = false;
      }
    if (!degrees_ok) return;
    int loops = 0;
    for (std::size_t i = 0; i < degree.size(); ++i)
      if (degree[i] != 0 && find(static_cast<int>(i)) == static_cast<int>(i)) ++loops;
    if (loops > 1)
      checker_.error(curves_ptr,
                     "the curves form " + std::to_string(loops) +
                         " separate loops; give one closed loop (holes are not supported)");
  }

  const json& j_;
  const std::string& pointer_;
  RuleChecker& checker_;
  GeometrySpec g_;
  std::vector<std::vector<std::string>> groups_of_curve_;
};

}  // namespace

ObjectRulePtr geometry_rule(const CaseReadOptions& options) {
  const CaseLimits& limits = options.limits;
  const std::size_t max = limits.max_geometry_entities;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the geometry";
  r->anchor = "geometry";
  ValueRule curve_indices =
      array_value(integer_value(Range::non_negative()), max, "array of curve indices");
  r->fields = {
      required_field("points", array_value(point_value(), max, "array of points [x, y]"),
                     "the points [x, y] of the geometry"),
      required_field("curves", array_value(object_value(curve_rule()), max, "array of curves"),
                     "lines and arcs forming one closed loop"),
      required_field(
          "groups",
          map_value(name_value(limits.max_name_length, "the group name"), curve_indices, max,
                    "object mapping each boundary group name to a list of curve indices", "groups"),
          "named lists of curve indices"),
  };
  r->hook = [](const json& j, const std::string& pointer, RuleChecker& checker) {
    GeometryChecks(j, pointer, checker).run();
  };
  r->notes =
      "indices name existing points and curves; a curve's end points differ; an arc's end points "
      "are equidistant from its centre (relative tolerance 1e-9) and it is not a half circle; "
      "every curve is in exactly one group; the curves form one closed loop";
  return r;
}

GeometrySpec read_geometry_section(const json& j) {
  GeometrySpec g;
  for (const auto& p : j.at("points"))
    g.points.emplace_back(p[0].get<double>(), p[1].get<double>());
  if (const auto it = j.find("curves"); it != j.end())
    for (const auto& c : *it) {
      GeometrySpec::Curve curve;
      curve.is_arc = c.at("type") == "arc";
      curve.points = {c.at("points")[0].get<int>(), c.at("points")[1].get<int>()};
      if (curve.is_arc) curve.center = c.at("center").get<int>();
      g.curves.push_back(curve);
    }
  if (const auto it = j.find("groups"); it != j.end())
    for (const auto& [name, list] : it->items())
      g.groups.push_back({name, list.get<std::vector<int>>()});
  return g;
}

double estimated_coarse_triangles(const GeometrySpec& g, double size) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
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
  return (hi - lo).prod() / (0.433 * size * size);
}

}  // namespace fosls
