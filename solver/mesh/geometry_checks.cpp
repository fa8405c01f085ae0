#include "mesh/geometry_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "mesh/plane_geometry.hpp"

namespace fosls {

namespace {

using plane::angle_of;
using plane::cross;
using plane::kPi;
using plane::num;
using plane::where;
using plane::wrap;

const std::string kGeometryField = "/geometry";

// ---------------------------------------------------------------------------------------------
// Geometry of one validated curve, for the intersection tests.

struct CurveShape {
  bool arc = false;
  int ia = -1, ib = -1;  // point indices of the end points
  Point a, b;
  Point c;                 // arc centre
  double r = 0;            // arc radius (of the start point)
  double start = 0;        // arc: counter-clockwise interval [start, start + width] on the circle
  double width = 0;        //
  Eigen::Vector2d lo, hi;  // bounding box

  /// Whether q (on the circle) lies on the arc, with angular tolerance eps.
  bool arc_contains(const Point& q, double eps) const {
    double d = wrap(angle_of(q - c) - start);
    return d <= width + eps || d >= 2 * kPi - eps;
  }
};

CurveShape make_shape(const GeometrySpec& g, const GeometrySpec::Curve& cv, double tol) {
  CurveShape s;
  s.arc = cv.is_arc;
  s.ia = cv.points[0];
  s.ib = cv.points[1];
  s.a = g.points[s.ia];
  s.b = g.points[s.ib];
  s.lo = s.a.cwiseMin(s.b);
  s.hi = s.a.cwiseMax(s.b);
  if (s.arc) {
    s.c = g.points[cv.center];
    s.r = (s.a - s.c).norm();
    double t0 = angle_of(s.a - s.c), t1 = angle_of(s.b - s.c);
    double sweep = wrap(t1 - t0);
    // The shorter way round: counter-clockwise when the sweep is below π, else clockwise.
    if (sweep <= kPi) {
      s.start = t0;
      s.width = sweep;
    } else {
      s.start = t1;
      s.width = 2 * kPi - sweep;
    }
    for (int k = 0; k < 4; ++k) {
      Point q = s.c + s.r * Point(std::cos(k * kPi / 2), std::sin(k * kPi / 2));
      if (s.arc_contains(q, 0.0)) {
        s.lo = s.lo.cwiseMin(q);
        s.hi = s.hi.cwiseMax(q);
      }
    }
  }
  s.lo.array() -= tol;
  s.hi.array() += tol;
  return s;
}

/// Points where two curves meet; `overlap` when they share a piece of positive length.
struct Meeting {
  std::vector<Point> points;
  bool overlap = false;
};

Meeting meet_segments(const CurveShape& p, const CurveShape& q, double tol) {
  Meeting m;
  const Point d1 = p.b - p.a, d2 = q.b - q.a;
  const double l1 = d1.norm(), l2 = d2.norm();
  const double denom = cross(d1, d2);
  if (std::abs(denom) <= 1e-12 * l1 * l2) {
    // Parallel: they meet only when collinear, along the common interval.
    if (std::abs(cross(d1, q.a - p.a)) / l1 > tol) return m;
    const Point u = d1 / l1;
    double s0 = u.dot(q.a - p.a), s1 = u.dot(q.b - p.a);
    double lo = std::max(0.0, std::min(s0, s1)), hi = std::min(l1, std::max(s0, s1));
    if (hi - lo > tol)
      m.overlap = true;
    else if (hi - lo >= -tol)
      m.points.push_back(p.a + 0.5 * (lo + hi) * u);
    return m;
  }
  const Point w = q.a - p.a;
  const double t = cross(w, d2) / denom, s = cross(w, d1) / denom;
  if (t >= -tol / l1 && t <= 1 + tol / l1 && s >= -tol / l2 && s <= 1 + tol / l2)
    m.points.push_back(p.a + t * d1);
  return m;
}

Meeting meet_segment_arc(const CurveShape& seg, const CurveShape& arc, double tol) {
  Meeting m;
  const Point d = seg.b - seg.a;
  const double len = d.norm();
  const Point u = d / len;
  // Foot of the perpendicular from the centre; the line meets the circle at foot ± h u.
  const double t_foot = u.dot(arc.c - seg.a);
  const Point foot = seg.a + t_foot * u;
  const double dist = (arc.c - foot).norm();
  if (dist > arc.r + tol) return m;
  const double h = std::sqrt(std::max(0.0, arc.r * arc.r - dist * dist));
  std::vector<double> ts = {t_foot - h, t_foot + h};
  if (h <= tol) ts = {t_foot};
  for (double t : ts) {
    if (t < -tol || t > len + tol) continue;
    Point x = seg.a + t * u;
    if (arc.arc_contains(x, tol / arc.r)) m.points.push_back(x);
  }
  return m;
}

Meeting meet_arcs(const CurveShape& p, const CurveShape& q, double tol) {
  Meeting m;
  const Point dc = q.c - p.c;
  const double dist = dc.norm();
  if (dist <= tol) {
    if (std::abs(p.r - q.r) > tol) return m;  // concentric, distinct circles
    // Same circle: overlap of the two angular intervals (the second may wrap past 2π).
    const double d = wrap(q.start - p.start);
    double common = std::max(0.0, std::min(p.width, d + q.width) - d) +
                    std::max(0.0, std::min(p.width, d - 2 * kPi + q.width));
    if (common * p.r > tol) {
      m.overlap = true;
      return m;
    }
    for (const Point& x : {q.a, q.b})
      if (p.arc_contains(x, tol / p.r)) m.points.push_back(x);
    for (const Point& x : {p.a, p.b})
      if (q.arc_contains(x, tol / q.r)) m.points.push_back(x);
    return m;
  }
  if (dist > p.r + q.r + tol || dist < std::abs(p.r - q.r) - tol) return m;
  const double a = (dist * dist + p.r * p.r - q.r * q.r) / (2 * dist);
  const double h = std::sqrt(std::max(0.0, p.r * p.r - a * a));
  const Point u = dc / dist, n(-u.y(), u.x());
  std::vector<Point> xs = {p.c + a * u + h * n, p.c + a * u - h * n};
  if (h <= tol) xs.resize(1);
  for (const Point& x : xs)
    if (p.arc_contains(x, tol / p.r) && q.arc_contains(x, tol / q.r)) m.points.push_back(x);
  return m;
}

Meeting meet(const CurveShape& p, const CurveShape& q, double tol) {
  if (!p.arc && !q.arc) return meet_segments(p, q, tol);
  if (!p.arc) return meet_segment_arc(p, q, tol);
  if (!q.arc) return meet_segment_arc(q, p, tol);
  return meet_arcs(p, q, tol);
}

std::string curve_ptr(int k) { return kGeometryField + "/curves/" + std::to_string(k); }
std::string point_ptr(int i) { return kGeometryField + "/points/" + std::to_string(i); }
std::string group_ptr(int g) { return kGeometryField + "/groups/" + std::to_string(g); }

/// Reports curves that cross, touch or overlap other than at a shared end point.
void check_intersections(const GeometrySpec& g, const std::vector<bool>& curve_ok, double tol,
                         std::vector<MeshProblem>& errors) {
  std::vector<CurveShape> shapes(g.curves.size());
  std::vector<int> order;
  for (std::size_t k = 0; k < g.curves.size(); ++k)
    if (curve_ok[k]) {
      shapes[k] = make_shape(g, g.curves[k], tol);
      order.push_back(static_cast<int>(k));
    }
  // Sweep along x so that only curves whose bounding boxes overlap are compared.
  std::sort(order.begin(), order.end(),
            [&](int i, int j) { return shapes[i].lo.x() < shapes[j].lo.x(); });
  constexpr int kMaxReported = 20;
  int reported = 0;
  for (std::size_t oi = 0; oi < order.size() && reported < kMaxReported; ++oi) {
    const CurveShape& p = shapes[order[oi]];
    for (std::size_t oj = oi + 1; oj < order.size() && reported < kMaxReported; ++oj) {
      const CurveShape& q = shapes[order[oj]];
      if (q.lo.x() > p.hi.x()) break;
      if (q.lo.y() > p.hi.y() || q.hi.y() < p.lo.y()) continue;
      const int i = std::min(order[oi], order[oj]), j = std::max(order[oi], order[oj]);
      Meeting m = meet(p, q, tol);
      if (m.overlap) {
        errors.push_back({curve_ptr(j), "curve " + std::to_string(j) + " overlaps curve " +
                                            std::to_string(i) +
                                            "; boundary curves may meet only "
                                            "at shared end points"});
        ++reported;
        continue;
      }
      for (const Point& x : m.points) {
        bool at_shared_end = false;
        for (int pa : {p.ia, p.ib})
          for (int qa : {q.ia, q.ib})
            if (pa == qa && (x - g.points[pa]).norm() <= 10 * tol) at_shared_end = true;
        if (at_shared_end) continue;
        errors.push_back(
            {curve_ptr(j), "curve " + std::to_string(j) + " crosses or touches curve " +
                               std::to_string(i) + " at " + where(x) +
                               "; boundary curves may meet only at shared end points"});
        ++reported;
        break;
      }
    }
  }
}

}  // namespace

std::vector<int> walk_loop(const GeometrySpec& g) {
  const int m = static_cast<int>(g.curves.size());
  std::unordered_map<int, std::vector<int>> at_point;
  for (int k = 0; k < m; ++k)
    for (int p : g.curves[k].points) at_point[p].push_back(k);
  std::vector<int> loop;
  std::vector<bool> used(m, false);
  int k = 0, end = g.curves[0].points[1];
  loop.push_back(1);
  used[0] = true;
  while (true) {
    const auto& here = at_point[end];
    int next = here[0] == k ? here[1] : here[0];
    if (used[next]) break;
    used[next] = true;
    const bool forward = g.curves[next].points[0] == end;
    loop.push_back(forward ? next + 1 : -(next + 1));
    end = forward ? g.curves[next].points[1] : g.curves[next].points[0];
    k = next;
  }
  if (static_cast<int>(loop.size()) != m) return {};
  return loop;
}

namespace {

/// Reports points with non-finite coordinates (point_ok false); returns the geometric
/// tolerance, 1e-9 of the extent of the finite points.
double check_points(const GeometrySpec& g, std::vector<bool>& point_ok,
                    std::vector<MeshProblem>& errors) {
  const int np = static_cast<int>(g.points.size());
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector2d hi = -lo;
  for (int i = 0; i < np; ++i) {
    if (!g.points[i].allFinite()) {
      point_ok[i] = false;
      errors.push_back({point_ptr(i), "the coordinates must be finite numbers"});
      continue;
    }
    lo = lo.cwiseMin(g.points[i]);
    hi = hi.cwiseMax(g.points[i]);
  }
  const double scale = np > 0 && (hi - lo).allFinite() ? std::max((hi - lo).norm(), 1e-300) : 1.0;
  const double tol = 1e-9 * scale;
  return tol;
}

/// Reports curves whose points do not exist, of zero length, or arcs that are not arcs;
/// returns which curves are usable.
std::vector<bool> check_curves(const GeometrySpec& g, const std::vector<bool>& point_ok, double tol,
                               std::vector<MeshProblem>& errors) {
  const int np = static_cast<int>(g.points.size());
  const int nc = static_cast<int>(g.curves.size());
  auto valid_point = [&](int i) { return i >= 0 && i < np && point_ok[i]; };
  std::vector<bool> curve_ok(nc, true);
  for (int k = 0; k < nc; ++k) {
    const auto& cv = g.curves[k];
    for (int e = 0; e < 2; ++e)
      if (!valid_point(cv.points[e])) {
        curve_ok[k] = false;
        errors.push_back({curve_ptr(k) + "/points/" + std::to_string(e),
                          "point index " + std::to_string(cv.points[e]) +
                              " does not name a point with finite coordinates (there are " +
                              std::to_string(np) + " points)"});
      }
    if (cv.is_arc && !valid_point(cv.center)) {
      curve_ok[k] = false;
      errors.push_back({curve_ptr(k) + "/center", "point index " + std::to_string(cv.center) +
                                                      " does not name a point with finite "
                                                      "coordinates (there are " +
                                                      std::to_string(np) + " points)"});
    }
    if (!curve_ok[k]) continue;
    const Point a = g.points[cv.points[0]], b = g.points[cv.points[1]];
    if (cv.points[0] == cv.points[1] || (b - a).norm() <= tol) {
      curve_ok[k] = false;
      errors.push_back({curve_ptr(k), "the curve has zero length: its end points coincide"});
      continue;
    }
    if (!cv.is_arc) continue;
    const Point c = g.points[cv.center];
    const double r0 = (a - c).norm(), r1 = (b - c).norm();
    if (r0 <= tol || r1 <= tol) {
      curve_ok[k] = false;
      errors.push_back({curve_ptr(k), "an end point of the arc coincides with its centre"});
    } else if (std::abs(r0 - r1) > 1e-9 * std::max(r0, r1)) {
      curve_ok[k] = false;
      errors.push_back({curve_ptr(k), "the arc's start and end are at distances " + num(r0) +
                                          " and " + num(r1) +
                                          " from its centre; they must be equal (to 1e-9 "
                                          "relative)"});
    } else if (std::abs(cross(a - c, b - c)) <= 1e-9 * r0 * r1 && (a - c).dot(b - c) < 0) {
      curve_ok[k] = false;
      errors.push_back({curve_ptr(k),
                        "the arc spans half a circle, so the shorter way round is "
                        "ambiguous; split it into two arcs"});
    }
  }
  return curve_ok;
}

/// Groups: non-empty unique names, every curve in exactly one group.
void check_groups(const GeometrySpec& g, std::vector<MeshProblem>& errors) {
  const int nc = static_cast<int>(g.curves.size());
  std::vector<int> group_of(nc, -1);
  for (int gi = 0; gi < static_cast<int>(g.groups.size()); ++gi) {
    const auto& grp = g.groups[gi];
    if (grp.name.empty())
      errors.push_back({group_ptr(gi) + "/name", "the group name must not be empty"});
    for (int gj = 0; gj < gi; ++gj)
      if (!grp.name.empty() && g.groups[gj].name == grp.name) {
        errors.push_back(
            {group_ptr(gi) + "/name", "the name '" + grp.name + "' is already used by group " +
                                          std::to_string(gj) + "; group names must be unique"});
        break;
      }
    if (grp.curves.empty())
      errors.push_back({group_ptr(gi) + "/curves", "the group has no curves"});
    for (int j = 0; j < static_cast<int>(grp.curves.size()); ++j) {
      const int k = grp.curves[j];
      const std::string ptr = group_ptr(gi) + "/curves/" + std::to_string(j);
      if (k < 0 || k >= nc) {
        errors.push_back({ptr, "curve index " + std::to_string(k) +
                                   " does not name a curve (there are " + std::to_string(nc) +
                                   " curves)"});
      } else if (group_of[k] >= 0) {
        errors.push_back({ptr, "curve " + std::to_string(k) + " is already in group '" +
                                   g.groups[group_of[k]].name +
                                   "'; every curve must be in exactly one group"});
      } else {
        group_of[k] = gi;
      }
    }
  }
  for (int k = 0; k < nc; ++k)
    if (group_of[k] < 0)
      errors.push_back({curve_ptr(k), "curve " + std::to_string(k) +
                                          " is in no group; every curve must be in exactly one "
                                          "group"});
}

/// One closed loop: distinct points at one place, every end point joining exactly two curves,
/// and all curves connected.
void check_one_loop(const GeometrySpec& g, double tol, std::vector<MeshProblem>& errors) {
  const int np = static_cast<int>(g.points.size());
  std::vector<int> degree(np, 0);
  for (const auto& cv : g.curves)
    for (int p : cv.points) ++degree[p];
  std::vector<int> ends;
  for (int i = 0; i < np; ++i)
    if (degree[i] > 0) ends.push_back(i);
  std::sort(ends.begin(), ends.end(),
            [&](int i, int j) { return g.points[i].x() < g.points[j].x(); });
  bool loop_ok = true;
  for (std::size_t a = 0; a < ends.size(); ++a)
    for (std::size_t b = a + 1;
         b < ends.size() && g.points[ends[b]].x() - g.points[ends[a]].x() <= tol; ++b)
      if ((g.points[ends[b]] - g.points[ends[a]]).norm() <= tol) {
        const int i = std::min(ends[a], ends[b]), j = std::max(ends[a], ends[b]);
        errors.push_back({point_ptr(j), "point " + std::to_string(j) + " coincides with point " +
                                            std::to_string(i) +
                                            "; curves that meet must share one point index"});
        loop_ok = false;
      }
  for (int i = 0; i < np; ++i)
    if (degree[i] != 0 && degree[i] != 2) {
      errors.push_back({point_ptr(i), "point " + std::to_string(i) + " is an end of " +
                                          std::to_string(degree[i]) +
                                          " curves; the curves must form one closed loop, "
                                          "where every end point joins exactly two curves"});
      loop_ok = false;
    }
  if (loop_ok && walk_loop(g).empty())
    errors.push_back({kGeometryField + "/curves",
                      "the curves form several separate loops; the boundary must be one closed "
                      "loop (holes are not supported)"});
}

}  // namespace

std::vector<MeshProblem> validate_geometry(const GeometrySpec& g) {
  std::vector<MeshProblem> errors;
  if (g.curves.empty()) {
    errors.push_back({kGeometryField + "/curves",
                      "the geometry has no curves; give at least "
                      "one closed loop of segments and arcs"});
    return errors;
  }
  std::vector<bool> point_ok(g.points.size(), true);
  const double tol = check_points(g, point_ok, errors);
  const std::vector<bool> curve_ok = check_curves(g, point_ok, tol, errors);
  check_groups(g, errors);
  if (std::find(curve_ok.begin(), curve_ok.end(), false) != curve_ok.end()) return errors;
  check_one_loop(g, tol, errors);
  check_intersections(g, curve_ok, tol, errors);
  return errors;
}

}  // namespace fosls
