#include "post/pressure_section.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>

namespace fosls {

namespace {

/// The s-range along `direction` of the points where the plane with unit normal `m` through
/// `origin` meets triangle x; none when it misses it or meets it in a point. A vertex within
/// `tolerance` of the plane is on it (the origin, a centre of pressure, carries rounding).
std::optional<std::pair<double, double>> cut(const std::array<Point3, 3>& x, const Point3& origin,
                                             const Point3& m, const Point3& direction,
                                             double tolerance) {
  std::array<double, 3> d;
  for (int i = 0; i < 3; ++i) {
    d[i] = (x[i] - origin).dot(m);
    if (std::abs(d[i]) <= tolerance) d[i] = 0.0;
  }
  std::vector<double> s;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (d[i] == 0.0) s.push_back((x[i] - origin).dot(direction));
    if (d[i] * d[j] < 0.0) {
      const Point3 p = x[i] + d[i] / (d[i] - d[j]) * (x[j] - x[i]);
      s.push_back((p - origin).dot(direction));
    }
  }
  if (s.size() < 2) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
  const double size = std::max({(x[1] - x[0]).norm(), (x[2] - x[1]).norm(), (x[0] - x[2]).norm()});
  if (!(*hi - *lo > 1e-6 * size)) return std::nullopt;
  return std::make_pair(*lo, *hi);
}

/// One step for the two faces on either side of an edge that lies in the plane: both are cut
/// along it, and its pressure is their mean.
std::vector<SectionStep> merged_edges(const std::vector<SectionStep>& sorted, double tolerance) {
  std::vector<SectionStep> out;
  for (const SectionStep& s : sorted) {
    SectionStep* last = out.empty() ? nullptr : &out.back();
    if (last && std::abs(last->from - s.from) <= tolerance &&
        std::abs(last->to - s.to) <= tolerance)
      last->pressure = 0.5 * (last->pressure + s.pressure);
    else
      out.push_back(s);
  }
  return out;
}

}  // namespace

std::vector<SectionStep> pressure_section(const TetMesh& mesh, const std::vector<int>& faces,
                                          const std::vector<double>& pressure, const Point3& origin,
                                          const Point3& direction, const Point3& normal) {
  const Point3 m = direction.cross(normal).normalized();
  const double tolerance = 1e-8 * mesh.diameter();
  std::vector<SectionStep> steps;
  for (int f : faces) {
    const std::array<int, 3>& v = mesh.face(f);
    const auto range = cut({mesh.vertex(v[0]), mesh.vertex(v[1]), mesh.vertex(v[2])}, origin, m,
                           direction, tolerance);
    if (range) steps.push_back({range->first, range->second, pressure[f]});
  }
  std::sort(steps.begin(), steps.end(),
            [](const SectionStep& a, const SectionStep& b) { return a.from < b.from; });
  return merged_edges(steps, tolerance);
}

}  // namespace fosls
