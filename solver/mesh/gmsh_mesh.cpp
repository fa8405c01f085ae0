#include "mesh/gmsh_mesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace fosls {

std::mutex& gmsh_mutex() {
  static std::mutex m;
  return m;
}

void ensure_gmsh_initialized() {
  // Guarded by gmsh_mutex(), held by the caller; never finalised: other threads may mesh until
  // the process exits.
  static bool initialized = false;
  if (initialized) return;
  gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
  gmsh::option::setNumber("General.Terminal", 0);
  initialized = true;
}

namespace {

constexpr double kPi = std::numbers::pi;
const std::string kGeometryPointer = "/mesh/geometry";
const std::string kGeoFilePointer = "/mesh/geo_file";
const std::string kSizePointer = "/mesh/size";

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

std::string where(const Point& p) { return "(" + num(p.x()) + ", " + num(p.y()) + ")"; }

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Angle of v in [0, 2π).
double angle_of(const Point& v) {
  double a = std::atan2(v.y(), v.x());
  return a < 0 ? a + 2 * kPi : a;
}

/// Wraps x into [0, 2π).
double wrap(double x) {
  x = std::fmod(x, 2 * kPi);
  return x < 0 ? x + 2 * kPi : x;
}

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

std::string curve_ptr(int k) { return kGeometryPointer + "/curves/" + std::to_string(k); }
std::string point_ptr(int i) { return kGeometryPointer + "/points/" + std::to_string(i); }
std::string group_ptr(int g) { return kGeometryPointer + "/groups/" + std::to_string(g); }

/// Reports curves that cross, touch or overlap other than at a shared end point.
void check_intersections(const GeometrySpec& g, const std::vector<bool>& curve_ok, double tol,
                         std::vector<CaseError>& errors) {
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

/// Signed gmsh curve tags (index + 1) of the loop in walking order; empty when not one loop.
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

// ---------------------------------------------------------------------------------------------
// Mesh size guard: estimated triangle count ∫ 1 / (√3/4 h²) over the domain.

std::vector<Point> polygonize(const GeometrySpec& g, const std::vector<int>& loop) {
  std::vector<Point> poly;
  for (int signed_tag : loop) {
    const auto& cv = g.curves[std::abs(signed_tag) - 1];
    Point a = g.points[cv.points[0]], b = g.points[cv.points[1]];
    if (signed_tag < 0) std::swap(a, b);
    if (!cv.is_arc) {
      poly.push_back(a);
      continue;
    }
    const Point c = g.points[cv.center];
    const double r = (a - c).norm();
    double t0 = angle_of(a - c), sweep = wrap(angle_of(b - c) - t0);
    if (sweep > kPi) sweep -= 2 * kPi;
    constexpr int kPieces = 16;
    for (int i = 0; i < kPieces; ++i) {
      double t = t0 + sweep * i / kPieces;
      poly.push_back(c + r * Point(std::cos(t), std::sin(t)));
    }
  }
  return poly;
}

bool inside(const std::vector<Point>& poly, const Point& x) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Point &a = poly[i], &b = poly[j];
    if ((a.y() > x.y()) != (b.y() > x.y()) &&
        x.x() < a.x() + (x.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      in = !in;
  }
  return in;
}

double estimate_triangles(const std::vector<Point>& poly, const MeshSizeField& size) {
  Eigen::Vector2d lo = poly[0], hi = poly[0];
  for (const Point& p : poly) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  constexpr int kSamples = 64;
  const Eigen::Vector2d cell = (hi - lo) / kSamples;
  const double cell_area = cell.x() * cell.y();
  double count = 0.0;
  bool any = false;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const Point x = lo + Eigen::Vector2d((i + 0.5) * cell.x(), (j + 0.5) * cell.y());
      if (!inside(poly, x)) continue;
      any = true;
      const double h = size(x);
      if (!(h > 0) || !std::isfinite(h))
        throw CaseException(kSizePointer, "the mesh size must be positive and finite, got " +
                                              num(h) + " at " + where(x));
      count += cell_area / (std::sqrt(3.0) / 4 * h * h);
    }
  if (!any) {  // thinner than a sample cell: fall back to the size at the first point
    double area = 0.0;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
      area += 0.5 * cross(poly[j], poly[i]);
    const double h = size(poly[0]);
    count = std::abs(area) / (std::sqrt(3.0) / 4 * h * h);
  }
  return count;
}

// ---------------------------------------------------------------------------------------------
// gmsh model → Mesh.

/// A curve entity of the gmsh model and where its line elements go.
struct CurveEntity {
  int tag = 0;
  int group = -1;
  int curve = -1;  ///< index into the BoundaryCurve list, -1 when straight
};

/// Runs f, turning everything gmsh can throw into a CaseException at `pointer`.
template <class F>
auto guarded(const std::string& pointer, F&& f) {
  try {
    return f();
  } catch (const CaseException&) {
    throw;
  } catch (const std::string& s) {
    throw CaseException(pointer, "gmsh failed: " + s);
  } catch (const std::exception& e) {
    throw CaseException(pointer, std::string("gmsh failed: ") + e.what());
  } catch (...) {
    throw CaseException(pointer, "gmsh failed with an unknown error");
  }
}

/// Clears the gmsh model and size callback when a build ends, however it ends: the callback
/// refers to a size field that is about to go out of scope.
struct ModelScope {
  ModelScope() { gmsh::clear(); }
  ~ModelScope() {
    try {
      gmsh::model::mesh::removeSizeCallback();
      gmsh::clear();
    } catch (...) {
    }
  }
  ModelScope(const ModelScope&) = delete;
  ModelScope& operator=(const ModelScope&) = delete;
};

/// Options every build relies on; set each time because a .geo script may have changed them.
void set_common_options() {
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.AbortOnError", 2);
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads1D", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::option::setNumber("Mesh.RecombineAll", 0);
  gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 0);
  gmsh::option::setNumber("Mesh.RandomSeed", 1);
}

/// Runs a .geo script. gmsh 4.8 leaves its script parser broken when a parse error is thrown
/// as an exception (every later file then reads as empty), so errors are only logged while
/// the script runs and are collected from the log afterwards.
void run_geo_script(const std::string& path) {
  struct Restore {
    ~Restore() {
      try {
        gmsh::logger::stop();
        gmsh::option::setNumber("General.AbortOnError", 2);
      } catch (...) {
      }
    }
  };
  gmsh::option::setNumber("General.AbortOnError", 0);
  gmsh::logger::start();
  Restore restore;
  gmsh::open(path);
  std::vector<std::string> log;
  gmsh::logger::get(log);
  std::string errors;
  int count = 0;
  for (const auto& line : log)
    if (line.rfind("Error: ", 0) == 0 && count++ < 3)
      errors += (errors.empty() ? "" : "; ") + line.substr(7);
  if (!errors.empty()) throw CaseException(kGeoFilePointer, "the .geo script failed: " + errors);
}

std::string last_gmsh_error() {
  std::string err;
  try {
    gmsh::logger::getLastError(err);
  } catch (...) {
  }
  return err;
}

/// Reads nodes, triangles and the line elements of `entities` from the current gmsh model.
Mesh extract_mesh(const std::vector<CurveEntity>& entities, std::vector<std::string> group_names,
                  std::vector<BoundaryCurve> curves, const std::string& pointer,
                  const std::string& hint) {
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, params;
  gmsh::model::mesh::getNodes(node_tags, coords, params, -1, -1, false, false);
  std::unordered_map<std::size_t, int> raw_index;
  for (std::size_t i = 0; i < node_tags.size(); ++i) raw_index[node_tags[i]] = static_cast<int>(i);

  // Interior nodes of arcs move onto the exact circle (gmsh places them to round-off); the
  // arc's end points are the user's points and stay where they are.
  for (const auto& ent : entities) {
    if (ent.curve < 0) continue;
    std::vector<std::size_t> tags;
    std::vector<double> xyz, uv;
    gmsh::model::mesh::getNodes(tags, xyz, uv, 1, ent.tag, false, false);
    for (std::size_t t : tags) {
      const int i = raw_index.at(t);
      Point p = curves[ent.curve].project(Point(coords[3 * i], coords[3 * i + 1]));
      coords[3 * i] = p.x();
      coords[3 * i + 1] = p.y();
    }
  }

  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elem_tags, elem_nodes;
  gmsh::model::mesh::getElements(types, elem_tags, elem_nodes, 2, -1);
  std::vector<int> index(node_tags.size(), -1);
  std::vector<Point> vertices;
  auto vertex = [&](std::size_t tag) {
    const int i = raw_index.at(tag);
    if (index[i] < 0) {
      if (coords[3 * i + 2] != 0.0)
        throw CaseException(pointer, "the mesh does not lie in the plane z = 0 (a node has z = " +
                                         num(coords[3 * i + 2]) +
                                         "); only 2D meshes are supported");
      index[i] = static_cast<int>(vertices.size());
      vertices.emplace_back(coords[3 * i], coords[3 * i + 1]);
    }
    return index[i];
  };
  std::vector<std::array<int, 3>> triangles;
  for (std::size_t b = 0; b < types.size(); ++b) {
    if (types[b] == 3)
      throw CaseException(pointer,
                          "gmsh produced quadrangles; only triangles are supported "
                          "(remove Recombine from the script)");
    if (types[b] != 2)
      throw CaseException(pointer, "gmsh produced 2D elements of type " + std::to_string(types[b]) +
                                       "; only 3-node triangles are supported (Mesh.ElementOrder "
                                       "= 1)");
    const auto& nodes = elem_nodes[b];
    for (std::size_t e = 0; e + 2 < nodes.size(); e += 3)
      triangles.push_back({vertex(nodes[e]), vertex(nodes[e + 1]), vertex(nodes[e + 2])});
  }
  if (triangles.empty()) {
    std::string err = last_gmsh_error();
    throw CaseException(pointer, "gmsh produced no triangles" +
                                     (err.empty() ? std::string(hint) : " (" + err + ")" + hint));
  }

  std::vector<BoundarySegment> segments;
  for (const auto& ent : entities) {
    gmsh::model::mesh::getElements(types, elem_tags, elem_nodes, 1, ent.tag);
    for (std::size_t b = 0; b < types.size(); ++b) {
      if (types[b] != 1)
        throw CaseException(pointer, "gmsh produced line elements of type " +
                                         std::to_string(types[b]) +
                                         "; only 2-node lines are supported");
      const auto& nodes = elem_nodes[b];
      for (std::size_t e = 0; e + 1 < nodes.size(); e += 2) {
        const int i0 = index[raw_index.at(nodes[e])], i1 = index[raw_index.at(nodes[e + 1])];
        if (i0 < 0 || i1 < 0)
          throw CaseException(pointer, "a boundary curve of group '" + group_names[ent.group] +
                                           "' is not on the boundary of the meshed surface" + hint);
        segments.push_back({i0, i1, ent.group, ent.curve});
      }
    }
  }
  try {
    return Mesh(std::move(vertices), std::move(triangles), std::move(segments),
                std::move(group_names), std::move(curves));
  } catch (const std::invalid_argument& e) {
    throw CaseException(pointer,
                        std::string("the generated mesh is not valid: ") + e.what() + hint);
  }
}

/// Circle through three points; nullopt when they are (nearly) collinear.
std::optional<BoundaryCurve> circle_through(const Point& a, const Point& b, const Point& c) {
  const Point ab = b - a, ac = c - a;
  const double d = 2 * cross(ab, ac);
  if (std::abs(d) <= 1e-12 * ab.squaredNorm() + 1e-300) return std::nullopt;
  const Point o = a + Point(ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm(),
                            ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) /
                          d;
  return BoundaryCurve{o, (a - o).norm()};
}

/// The circle a gmsh curve entity lies on, when it is a circle arc.
std::optional<BoundaryCurve> circle_of_entity(int tag) {
  std::string type;
  gmsh::model::getType(1, tag, type);
  if (type != "Circle") return std::nullopt;
  std::vector<double> lo, hi;
  gmsh::model::getParametrizationBounds(1, tag, lo, hi);
  if (lo.empty() || hi.empty()) return std::nullopt;
  std::vector<double> ts;
  for (double f : {0.0, 0.5, 1.0, 0.25, 0.75}) ts.push_back(lo[0] + f * (hi[0] - lo[0]));
  std::vector<double> xyz;
  gmsh::model::getValue(1, tag, ts, xyz);
  if (xyz.size() != 15) return std::nullopt;
  auto pt = [&](int i) { return Point(xyz[3 * i], xyz[3 * i + 1]); };
  auto circle = circle_through(pt(0), pt(1), pt(2));
  if (!circle) return std::nullopt;
  for (int i = 3; i < 5; ++i)
    if (std::abs((pt(i) - circle->center).norm() - circle->radius) > 1e-9 * circle->radius)
      return std::nullopt;
  return circle;
}

}  // namespace

// -----------------------------------------------------------------------------------------------

std::vector<CaseError> validate_geometry(const GeometrySpec& g) {
  std::vector<CaseError> errors;
  const int np = static_cast<int>(g.points.size());
  const int nc = static_cast<int>(g.curves.size());
  if (nc == 0) {
    errors.push_back({kGeometryPointer + "/curves",
                      "the geometry has no curves; give at least "
                      "one closed loop of segments and arcs"});
    return errors;
  }
  std::vector<bool> point_ok(np, true);
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

  // Groups: non-empty unique names, every curve in exactly one group.
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

  if (std::find(curve_ok.begin(), curve_ok.end(), false) != curve_ok.end()) return errors;

  // One closed loop: distinct points at one place, every end point joining exactly two curves,
  // and all curves connected.
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
  if (loop_ok && walk_loop(g).empty()) {
    errors.push_back({kGeometryPointer + "/curves",
                      "the curves form several separate loops; the boundary must be one closed "
                      "loop (holes are not supported)"});
    loop_ok = false;
  }
  check_intersections(g, curve_ok, tol, errors);
  return errors;
}

Mesh mesh_from_geometry(const GeometrySpec& geometry, double size) {
  if (!(size > 0) || !std::isfinite(size))
    throw CaseException(kSizePointer, "the mesh size must be a positive number");
  return mesh_from_geometry(geometry, [size](const Point&) { return size; });
}

Mesh mesh_from_geometry(const GeometrySpec& g, const MeshSizeField& size) {
  if (auto errors = validate_geometry(g); !errors.empty()) throw CaseException(std::move(errors));
  const std::vector<int> loop = walk_loop(g);
  const double estimate = estimate_triangles(polygonize(g, loop), size);
  if (estimate > kMaxCoarseTriangles)
    throw CaseException(kSizePointer, "the mesh size is too small for this geometry: about " +
                                          num(estimate) + " coarse triangles (at most " +
                                          num(kMaxCoarseTriangles) +
                                          "); use a larger size and refinements instead");

  // Arcs on one circle (same centre point, same radius) share one BoundaryCurve.
  std::vector<BoundaryCurve> circles;
  std::vector<int> circle_center;
  std::vector<int> curve_circle(g.curves.size(), -1);
  for (std::size_t k = 0; k < g.curves.size(); ++k) {
    const auto& cv = g.curves[k];
    if (!cv.is_arc) continue;
    const Point c = g.points[cv.center];
    const double r = (g.points[cv.points[0]] - c).norm();
    for (std::size_t i = 0; i < circles.size() && curve_circle[k] < 0; ++i)
      if (circle_center[i] == cv.center && std::abs(circles[i].radius - r) <= 1e-9 * r)
        curve_circle[k] = static_cast<int>(i);
    if (curve_circle[k] < 0) {
      curve_circle[k] = static_cast<int>(circles.size());
      circles.push_back({c, r});
      circle_center.push_back(cv.center);
    }
  }
  std::vector<CurveEntity> entities;
  std::vector<std::string> names;
  for (std::size_t gi = 0; gi < g.groups.size(); ++gi) {
    names.push_back(g.groups[gi].name);
    for (int k : g.groups[gi].curves)
      entities.push_back({k + 1, static_cast<int>(gi), curve_circle[k]});
  }

  std::lock_guard<std::mutex> lock(gmsh_mutex());
  return guarded(kGeometryPointer, [&] {
    ensure_gmsh_initialized();
    ModelScope scope;
    set_common_options();
    namespace geo = gmsh::model::geo;
    std::vector<bool> needed(g.points.size(), false);
    for (const auto& cv : g.curves) {
      needed[cv.points[0]] = needed[cv.points[1]] = true;
      if (cv.is_arc) needed[cv.center] = true;
    }
    for (std::size_t i = 0; i < g.points.size(); ++i)
      if (needed[i])
        geo::addPoint(g.points[i].x(), g.points[i].y(), 0.0, 0.0, static_cast<int>(i) + 1);
    for (std::size_t k = 0; k < g.curves.size(); ++k) {
      const auto& cv = g.curves[k];
      const int tag = static_cast<int>(k) + 1;
      if (cv.is_arc)
        geo::addCircleArc(cv.points[0] + 1, cv.center + 1, cv.points[1] + 1, tag);
      else
        geo::addLine(cv.points[0] + 1, cv.points[1] + 1, tag);
    }
    geo::addCurveLoop(loop, 1);
    geo::addPlaneSurface({1}, 1);
    for (std::size_t gi = 0; gi < g.groups.size(); ++gi) {
      std::vector<int> tags;
      for (int k : g.groups[gi].curves) tags.push_back(k + 1);
      const int ptag = geo::addPhysicalGroup(1, tags, static_cast<int>(gi) + 1);
      gmsh::model::setPhysicalName(1, ptag, g.groups[gi].name);
    }
    geo::addPhysicalGroup(2, {1}, 1);
    geo::synchronize();

    set_common_options();
    gmsh::option::setNumber("Mesh.Algorithm", 6);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
    gmsh::option::setNumber("Mesh.MeshSizeFactor", 1);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::model::mesh::setSizeCallback(
        [&size](int, int, double x, double y, double) { return size(Point(x, y)); });
    gmsh::model::mesh::generate(2);
    return extract_mesh(entities, names, circles, kGeometryPointer, "");
  });
}

Mesh mesh_from_geo_file(const std::string& path, double size) {
  if (!(size > 0) || !std::isfinite(size))
    throw CaseException(kSizePointer, "the mesh size must be a positive number");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || !std::ifstream(path).good())
    throw CaseException(kGeoFilePointer, "cannot read the .geo file '" + path +
                                             "': it does not exist or is not a readable file");

  std::lock_guard<std::mutex> lock(gmsh_mutex());
  return guarded(kGeoFilePointer, [&] {
    ensure_gmsh_initialized();
    ModelScope scope;
    set_common_options();
    run_geo_script(path);
    set_common_options();
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);

    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    if (surfaces.empty())
      throw CaseException(kGeoFilePointer,
                          "the .geo file defines no surface to mesh; add a "
                          "Plane Surface bounded by its curves");
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
    const double estimate = (x1 - x0) * (y1 - y0) / (std::sqrt(3.0) / 4 * size * size);
    if (!(estimate <= kMaxCoarseTriangles))
      throw CaseException(kSizePointer, "the mesh size is too small for this geometry: up to " +
                                            num(estimate) + " coarse triangles (at most " +
                                            num(kMaxCoarseTriangles) + ")");

    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, 1);
    if (groups.empty())
      throw CaseException(kGeoFilePointer,
                          "the .geo file defines no physical curves; put every boundary curve "
                          "in a Physical Curve, whose name becomes the boundary group");
    std::sort(groups.begin(), groups.end());
    std::vector<std::string> names;
    std::vector<BoundaryCurve> circles;
    std::vector<CurveEntity> entities;
    std::unordered_map<int, std::string> group_of_entity;
    for (const auto& [dim, ptag] : groups) {
      std::string name;
      gmsh::model::getPhysicalName(1, ptag, name);
      if (name.empty()) name = std::to_string(ptag);
      auto it = std::find(names.begin(), names.end(), name);
      const int gi = static_cast<int>(it - names.begin());
      if (it == names.end()) names.push_back(name);
      std::vector<int> tags;
      gmsh::model::getEntitiesForPhysicalGroup(1, ptag, tags);
      for (int tag : tags) {
        auto [prev, fresh] = group_of_entity.emplace(tag, name);
        if (!fresh) {
          if (prev->second == name) continue;
          throw CaseException(kGeoFilePointer,
                              "curve " + std::to_string(tag) + " is in the physical curves '" +
                                  prev->second + "' and '" + name +
                                  "'; every boundary curve must be in exactly one");
        }
        int curve = -1;
        if (auto circle = circle_of_entity(tag)) {
          curve = static_cast<int>(circles.size());
          circles.push_back(*circle);
        }
        entities.push_back({tag, gi, curve});
      }
    }
    gmsh::model::mesh::clear();
    gmsh::model::mesh::generate(2);
    return extract_mesh(entities, names, circles, kGeoFilePointer,
                        "; put every boundary curve of the .geo file in a Physical Curve and "
                        "mesh one plane surface in z = 0");
  });
}

}  // namespace fosls
