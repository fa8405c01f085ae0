#include "mesh/mesher_protocol.hpp"

#include <cmath>
#include <stdexcept>

namespace fosls {

namespace {

using nlohmann::json;

json points_to_json(const std::vector<Point>& points) {
  std::vector<double> flat;
  flat.reserve(2 * points.size());
  for (const Point& p : points) flat.insert(flat.end(), {p.x(), p.y()});
  return flat;
}

std::vector<Point> points_from_json(const json& j) {
  const auto flat = j.get<std::vector<double>>();
  if (flat.size() % 2 != 0) throw std::invalid_argument("odd number of coordinates");
  std::vector<Point> points;
  points.reserve(flat.size() / 2);
  for (std::size_t i = 0; i < flat.size(); i += 2) points.emplace_back(flat[i], flat[i + 1]);
  return points;
}

json geometry_to_json(const GeometrySpec& g) {
  json curves = json::array(), groups = json::array();
  for (const auto& c : g.curves) curves.push_back({c.is_arc, c.points[0], c.points[1], c.center});
  for (const auto& grp : g.groups) groups.push_back({{"name", grp.name}, {"curves", grp.curves}});
  return {{"points", points_to_json(g.points)}, {"curves", curves}, {"groups", groups}};
}

GeometrySpec geometry_from_json(const json& j) {
  GeometrySpec g;
  g.points = points_from_json(j.at("points"));
  for (const auto& c : j.at("curves"))
    g.curves.push_back(
        {c.at(0).get<bool>(), {c.at(1).get<int>(), c.at(2).get<int>()}, c.at(3).get<int>()});
  for (const auto& grp : j.at("groups"))
    g.groups.push_back(
        {grp.at("name").get<std::string>(), grp.at("curves").get<std::vector<int>>()});
  return g;
}

json size_to_json(const SizeField& s) {
  return {{"size", s.size},
          {"grading", s.grading},
          {"origin", {s.origin.x(), s.origin.y()}},
          {"reach", std::isinf(s.reach) ? json(nullptr) : json(s.reach)}};
}

SizeField size_from_json(const json& j) {
  SizeField s;
  s.size = j.at("size").get<double>();
  s.grading = j.at("grading").get<double>();
  s.origin = Point(j.at("origin").at(0).get<double>(), j.at("origin").at(1).get<double>());
  if (!j.at("reach").is_null()) s.reach = j.at("reach").get<double>();
  return s;
}

/// Runs f, turning nlohmann's type and range errors into std::invalid_argument.
template <class F>
auto reading(const char* what, F&& f) {
  try {
    return f();
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("not a mesher ") + what + ": " + e.what());
  }
}

}  // namespace

json request_to_json(const MeshRequest& request) {
  if (const auto* g = std::get_if<GeometryMeshRequest>(&request))
    return {{"geometry", geometry_to_json(g->geometry)}, {"size", size_to_json(g->size)}};
  if (const auto* f = std::get_if<GeoFile3dMeshRequest>(&request))
    return {{"geo_file_3d", f->path}, {"size", f->size}};
  const auto& f = std::get<GeoFileMeshRequest>(request);
  return {{"geo_file", f.path}, {"size", f.size}};
}

MeshRequest request_from_json(const json& j) {
  return reading("request", [&]() -> MeshRequest {
    if (j.contains("geo_file_3d"))
      return GeoFile3dMeshRequest{j.at("geo_file_3d").get<std::string>(),
                                  j.at("size").get<double>()};
    if (j.contains("geo_file"))
      return GeoFileMeshRequest{j.at("geo_file").get<std::string>(), j.at("size").get<double>()};
    return GeometryMeshRequest{geometry_from_json(j.at("geometry")), size_from_json(j.at("size"))};
  });
}

json mesh_answer(const MeshData& m) {
  std::vector<int> triangles, segments;
  triangles.reserve(3 * m.triangles.size());
  for (const auto& t : m.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
  segments.reserve(4 * m.segments.size());
  for (const auto& s : m.segments) segments.insert(segments.end(), {s.v0, s.v1, s.group, s.curve});
  json curves = json::array();
  for (const auto& c : m.curves) curves.push_back({c.center.x(), c.center.y(), c.radius});
  return {{"mesh",
           {{"vertices", points_to_json(m.vertices)},
            {"triangles", triangles},
            {"segments", segments},
            {"groups", m.group_names},
            {"curves", curves}}}};
}

json problems_answer(const std::vector<MeshProblem>& problems) {
  json list = json::array();
  for (const auto& p : problems) list.push_back({{"field", p.field}, {"detail", p.detail}});
  return {{"problems", list}};
}

namespace {

/// Throws the mesher's problems when the answer holds them.
void throw_problems(const json& j) {
  if (!j.is_object() || !j.contains("problems")) return;
  std::vector<MeshProblem> problems = reading("answer", [&] {
    std::vector<MeshProblem> list;
    for (const auto& p : j.at("problems"))
      list.push_back({p.at("field").get<std::string>(), p.at("detail").get<std::string>()});
    return list;
  });
  if (problems.empty()) throw std::invalid_argument("the mesher failed without saying why");
  throw MeshError(std::move(problems));
}

}  // namespace

json msh_answer(const std::string& msh_text) { return {{"msh", msh_text}}; }

std::string read_msh_answer(const json& j) {
  throw_problems(j);
  return reading("answer", [&] { return j.at("msh").get<std::string>(); });
}

MeshData read_answer(const json& j) {
  throw_problems(j);
  return reading("answer", [&] {
    const json& m = j.at("mesh");
    MeshData d;
    d.vertices = points_from_json(m.at("vertices"));
    const auto triangles = m.at("triangles").get<std::vector<int>>();
    const auto segments = m.at("segments").get<std::vector<int>>();
    if (triangles.size() % 3 != 0 || segments.size() % 4 != 0)
      throw std::invalid_argument("not a mesher answer: truncated triangles or segments");
    for (std::size_t i = 0; i < triangles.size(); i += 3)
      d.triangles.push_back({triangles[i], triangles[i + 1], triangles[i + 2]});
    for (std::size_t i = 0; i < segments.size(); i += 4)
      d.segments.push_back({segments[i], segments[i + 1], segments[i + 2], segments[i + 3]});
    d.group_names = m.at("groups").get<std::vector<std::string>>();
    for (const auto& c : m.at("curves"))
      d.curves.push_back(
          {Point(c.at(0).get<double>(), c.at(1).get<double>()), c.at(2).get<double>()});
    return d;
  });
}

}  // namespace fosls
