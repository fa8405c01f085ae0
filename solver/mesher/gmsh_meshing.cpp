#include "mesher/gmsh_meshing.hpp"

#include <gmsh.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>
#include <unordered_map>

#include "mesh/coarse_mesh_estimate.hpp"
#include "mesh/geometry_checks.hpp"
#include "mesh/plane_geometry.hpp"
#include "mesher/gmsh_session.hpp"

namespace fosls {

namespace {

using plane::cross;
using plane::num;

const std::string kGeometryField = "/geometry";
const std::string kGeoFileField = "/geo_file";
const std::string kSizeField = "/size";

// ---------------------------------------------------------------------------------------------
// gmsh model → MeshData.

/// A curve entity of the gmsh model and where its line elements go.
struct CurveEntity {
  int tag = 0;
  int group = -1;
  int curve = -1;  ///< index into the BoundaryCurve list, -1 when straight
};

/// Runs f, turning everything gmsh can throw (outside its parallel regions) into a MeshError
/// at `field`.
template <class F>
auto guarded(const std::string& field, F&& f) {
  try {
    return f();
  } catch (const MeshError&) {
    throw;
  } catch (const std::string& s) {
    throw MeshError(field, "gmsh failed: " + s);
  } catch (const std::bad_alloc&) {
    throw;  // the mesher reports it as running out of memory
  } catch (const std::exception& e) {
    throw MeshError(field, std::string("gmsh failed: ") + e.what());
  } catch (...) {
    throw MeshError(field, "gmsh failed with an unknown error");
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
  if (!errors.empty()) throw MeshError(kGeoFileField, "the .geo script failed: " + errors);
}

/// Runs a .geo script with the common options before and after it (it may change them) and
/// `size` as the largest edge length.
void open_geo_script(const std::string& path, double size) {
  set_common_options();
  run_geo_script(path);
  set_common_options();
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
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
MeshData extract_mesh(const std::vector<CurveEntity>& entities,
                      std::vector<std::string> group_names, std::vector<BoundaryCurve> curves,
                      const std::string& field, const std::string& hint) {
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
        throw MeshError(field, "the mesh does not lie in the plane z = 0 (a node has z = " +
                                   num(coords[3 * i + 2]) + "); only 2D meshes are supported");
      index[i] = static_cast<int>(vertices.size());
      vertices.emplace_back(coords[3 * i], coords[3 * i + 1]);
    }
    return index[i];
  };
  std::vector<std::array<int, 3>> triangles;
  for (std::size_t b = 0; b < types.size(); ++b) {
    if (types[b] == 3)
      throw MeshError(field,
                      "gmsh produced quadrangles; only triangles are supported "
                      "(remove Recombine from the script)");
    if (types[b] != 2)
      throw MeshError(field, "gmsh produced 2D elements of type " + std::to_string(types[b]) +
                                 "; only 3-node triangles are supported (Mesh.ElementOrder "
                                 "= 1)");
    const auto& nodes = elem_nodes[b];
    for (std::size_t e = 0; e + 2 < nodes.size(); e += 3)
      triangles.push_back({vertex(nodes[e]), vertex(nodes[e + 1]), vertex(nodes[e + 2])});
  }
  if (triangles.empty()) {
    std::string err = last_gmsh_error();
    throw MeshError(field, "gmsh produced no triangles" +
                               (err.empty() ? std::string(hint) : " (" + err + ")" + hint));
  }

  std::vector<BoundarySegment> segments;
  for (const auto& ent : entities) {
    gmsh::model::mesh::getElements(types, elem_tags, elem_nodes, 1, ent.tag);
    for (std::size_t b = 0; b < types.size(); ++b) {
      if (types[b] != 1)
        throw MeshError(field, "gmsh produced line elements of type " + std::to_string(types[b]) +
                                   "; only 2-node lines are supported");
      const auto& nodes = elem_nodes[b];
      for (std::size_t e = 0; e + 1 < nodes.size(); e += 2) {
        const int i0 = index[raw_index.at(nodes[e])], i1 = index[raw_index.at(nodes[e + 1])];
        if (i0 < 0 || i1 < 0)
          throw MeshError(field, "a boundary curve of group '" + group_names[ent.group] +
                                     "' is not on the boundary of the meshed surface" + hint);
        segments.push_back({i0, i1, ent.group, ent.curve});
      }
    }
  }
  return {std::move(vertices), std::move(triangles), std::move(segments), std::move(group_names),
          std::move(curves)};
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

namespace {

/// Arcs on one circle (same centre point, same radius) share one BoundaryCurve: the circles,
/// and each curve's circle (−1: a segment).
std::vector<BoundaryCurve> shared_circles(const GeometrySpec& g, std::vector<int>& curve_circle) {
  std::vector<BoundaryCurve> circles;
  std::vector<int> circle_center;
  curve_circle.assign(g.curves.size(), -1);
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
  return circles;
}

/// The geometry as gmsh's built-in (geo) model: points, curves, the loop, the surface and a
/// physical group per boundary group.
void add_geo_model(const GeometrySpec& g, const std::vector<int>& loop) {
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
}

/// Triangles sized by the size field alone (no size from points, boundary or curvature).
void set_size_field(const SizeField& size) {
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1e22);
  gmsh::option::setNumber("Mesh.MeshSizeFactor", 1);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::model::mesh::setSizeCallback(
      [&size](int, int, double x, double y, double) { return size.at(Point(x, y)); });
}

}  // namespace

MeshData mesh_geometry_with_gmsh(const GeometryMeshRequest& request) {
  const GeometrySpec& g = request.geometry;
  const SizeField& size = request.size;
  // The caller has refused sizes that are too small (coarse_mesh_estimate.hpp); the geometry is
  // checked again because meshing relies on it forming one valid loop.
  std::vector<MeshProblem> problems = check_size_field(size);
  if (problems.empty()) problems = validate_geometry(g);
  if (!problems.empty()) throw MeshError(std::move(problems));
  const std::vector<int> loop = walk_loop(g);
  std::vector<int> curve_circle;
  const std::vector<BoundaryCurve> circles = shared_circles(g, curve_circle);
  std::vector<CurveEntity> entities;
  std::vector<std::string> names;
  for (std::size_t gi = 0; gi < g.groups.size(); ++gi) {
    names.push_back(g.groups[gi].name);
    for (int k : g.groups[gi].curves)
      entities.push_back({k + 1, static_cast<int>(gi), curve_circle[k]});
  }

  std::lock_guard<std::mutex> lock(gmsh_mutex());
  return guarded(kGeometryField, [&] {
    ensure_gmsh_initialized();
    ModelScope scope;
    set_common_options();
    add_geo_model(g, loop);
    set_common_options();
    set_size_field(size);
    gmsh::model::mesh::generate(2);
    return extract_mesh(entities, names, circles, kGeometryField, "");
  });
}

MeshData mesh_geo_file_with_gmsh(const GeoFileMeshRequest& request) {
  const std::string& path = request.path;
  const double size = request.size;  // checked by the caller, like the file's readability
  std::lock_guard<std::mutex> lock(gmsh_mutex());
  return guarded(kGeoFileField, [&] {
    ensure_gmsh_initialized();
    ModelScope scope;
    open_geo_script(path, size);

    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    if (surfaces.empty())
      throw MeshError(kGeoFileField,
                      "the .geo file defines no surface to mesh; add a "
                      "Plane Surface bounded by its curves");
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
    const double estimate = (x1 - x0) * (y1 - y0) / (std::sqrt(3.0) / 4 * size * size);
    if (!(estimate <= kMaxCoarseTriangles))
      throw MeshError(kSizeField, "the mesh size is too small for this geometry: up to " +
                                      num(estimate) + " coarse triangles (at most " +
                                      num(kMaxCoarseTriangles) + ")");

    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, 1);
    if (groups.empty())
      throw MeshError(kGeoFileField,
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
          throw MeshError(kGeoFileField, "curve " + std::to_string(tag) +
                                             " is in the physical curves '" + prev->second +
                                             "' and '" + name +
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
    return extract_mesh(entities, names, circles, kGeoFileField,
                        "; put every boundary curve of the .geo file in a Physical Curve and "
                        "mesh one plane surface in z = 0");
  });
}

std::string mesh_geo_file_3d_with_gmsh(const GeoFile3dMeshRequest& request) {
  const double size = request.size;  // checked by the caller, like the file's readability
  std::lock_guard<std::mutex> lock(gmsh_mutex());
  return guarded(kGeoFileField, [&] {
    ensure_gmsh_initialized();
    ModelScope scope;
    open_geo_script(request.path, size);
    gmsh::vectorpair volumes, surfaces, groups;
    gmsh::model::getEntities(volumes, 3);
    if (volumes.empty())
      throw MeshError(kGeoFileField,
                      "the .geo file defines no volume to mesh; add a Volume bounded by its "
                      "surfaces (or a Box, Sphere, ... with SetFactory(\"OpenCASCADE\"))");
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
    // A regular tetrahedron of edge h has volume h³/(6√2).
    const double estimate =
        (x1 - x0) * (y1 - y0) * (z1 - z0) / (size * size * size / (6.0 * std::sqrt(2.0)));
    if (!(estimate <= kMaxCoarseTriangles))
      throw MeshError(kSizeField, "the mesh size is too small for this geometry: up to " +
                                      num(estimate) + " coarse tetrahedra (at most " +
                                      num(kMaxCoarseTriangles) + ")");
    gmsh::model::getPhysicalGroups(surfaces, 2);
    if (surfaces.empty())
      throw MeshError(kGeoFileField,
                      "the .geo file defines no physical surfaces; put every boundary surface "
                      "in a Physical Surface, whose name becomes the boundary group");
    gmsh::model::getPhysicalGroups(groups, 3);
    if (groups.empty()) {  // gmsh saves only physical groups' elements: the volume must be one
      std::vector<int> tags;
      for (const auto& [dim, tag] : volumes) tags.push_back(tag);
      gmsh::model::addPhysicalGroup(3, tags);
    }
    gmsh::model::mesh::generate(3);
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    const auto path = std::filesystem::temp_directory_path() /
                      ("fosls_mesher_" + std::to_string(::getpid()) + ".msh");
    gmsh::write(path.string());
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::filesystem::remove(path);
    return text.str();
  });
}

}  // namespace fosls
