#pragma once
// Degenerate declarative geometries for fuzz-style tests of the CLI and the service: long thin
// rectangles of several lengths, heights and sizes, slivers, spikes that come within a hair of
// another side, nearly coincident points, and random star polygons with tiny arms. Generated
// from a fixed seed, so every run sends the same cases. Each case has only a traction-free
// group: a case that meshes is then refused at /boundary (no Dirichlet group) without being
// solved, so every case must end in a refusal, and the test bounds its time by meshing alone.

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace fosls::testing {

struct DegenerateCase {
  std::string label;
  nlohmann::json case_json;
};

/// A case whose geometry is the closed polygon `points` with one group "all".
inline nlohmann::json polygon_case(const std::string& name,
                                   const std::vector<std::pair<double, double>>& points,
                                   double size) {
  nlohmann::json pts = nlohmann::json::array(), curves = nlohmann::json::array(),
                 all = nlohmann::json::array();
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) {
    pts.push_back({points[i].first, points[i].second});
    curves.push_back({{"type", "line"}, {"points", {i, (i + 1) % n}}});
    all.push_back(i);
  }
  return {{"name", name},
          {"mesh",
           {{"geometry", {{"points", pts}, {"curves", curves}, {"groups", {{"all", all}}}}},
            {"size", size},
            {"refinements", 0}}},
          {"material", {{"mu", 1}, {"lambda", 1}}},
          {"boundary", {{"all", {{"type", "neumann"}, {"traction", {0, 0}}}}}}};
}

/// `count` cases drawn (with `seed`) from every family above.
inline std::vector<DegenerateCase> degenerate_cases(unsigned seed, int count) {
  std::mt19937 rng(seed);
  auto pick = [&rng](const std::vector<double>& v) {
    return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)];
  };
  auto uniform = [&rng](double a, double b) { return std::uniform_real_distribution<>(a, b)(rng); };
  std::vector<DegenerateCase> cases;
  for (int k = 0; static_cast<int>(cases.size()) < count; ++k) {
    const std::string name = "degenerate-" + std::to_string(k);
    char label[160];
    switch (k % 5) {
      case 0: {  // long thin rectangle
        const double l = pick({0.5, 4, 50, 200}), h = pick({1e-4, 1e-6}),
                     s = pick({1e-3, 0.05, 1.0});
        std::snprintf(label, sizeof label, "rectangle %g x %g, size %g", l, h, s);
        cases.push_back({label, polygon_case(name, {{0, 0}, {l, 0}, {l, h}, {0, h}}, s)});
        break;
      }
      case 1: {  // sliver triangle
        const double e = pick({1e-3, 1e-6, 1e-9, 1e-12}), s = pick({0.1, 1e-3});
        std::snprintf(label, sizeof label, "sliver of height %g, size %g", e, s);
        cases.push_back({label, polygon_case(name, {{0, 0}, {1, 0}, {0.5, e}}, s)});
        break;
      }
      case 2: {  // a spike reaching down to within d of the bottom side
        const double d = pick({1e-4, 1e-7, 1e-9, 1e-10}), s = pick({0.05, 0.2});
        std::snprintf(label, sizeof label, "spike %g above a side, size %g", d, s);
        cases.push_back(
            {label, polygon_case(
                        name, {{0, 0}, {1, 0}, {1, 1}, {0.6, 1}, {0.5, d}, {0.4, 1}, {0, 1}}, s)});
        break;
      }
      case 3: {  // a point nearly coinciding with a corner
        const double d = pick({1e-6, 1e-8, 1e-9, 1e-11}), s = pick({0.1, 0.02});
        std::snprintf(label, sizeof label, "point %g from a corner, size %g", d, s);
        cases.push_back({label, polygon_case(name, {{0, 0}, {d, 0}, {1, 0}, {1, 1}, {0, 1}}, s)});
        break;
      }
      case 4: {  // random star polygon, some arms tiny
        const int n = std::uniform_int_distribution<>(5, 40)(rng);
        const double s = pick({0.3, 0.05, 0.01});
        std::vector<std::pair<double, double>> pts;
        for (int i = 0; i < n; ++i) {
          const double r = uniform(0, 1) < 0.2 ? pick({1e-3, 1e-6}) : uniform(0.2, 1.0);
          const double t = 2 * M_PI * (i + uniform(-0.45, 0.45)) / n;
          pts.push_back({r * std::cos(t), r * std::sin(t)});
        }
        std::snprintf(label, sizeof label, "star of %d points, size %g", n, s);
        cases.push_back({label, polygon_case(name, pts, s)});
        break;
      }
    }
  }
  return cases;
}

}  // namespace fosls::testing
