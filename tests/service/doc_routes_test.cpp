// Every HTTP route the documentation names exists: each "GET /v1/…" (with its method) and each
// bare "/v1/…", "/healthz" or "/metrics" path in README.md and docs/*.md must match a route of
// the server's route table (api_routes(), the table the server registers), so that a reader
// never follows a documented route into a 404.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "api_routes.hpp"

namespace fosls::service {
namespace {

struct DocRoute {
  std::string file;
  std::string method;  ///< empty for a bare path
  std::string path;
};

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<DocRoute> documented_routes() {
  const std::filesystem::path root = FOSLS_SOURCE_DIR;
  std::vector<std::filesystem::path> files = {root / "README.md"};
  for (const auto& entry : std::filesystem::directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") files.push_back(entry.path());
  // A path starts at a character that cannot continue a word or a file path.
  static const std::regex route(
      R"((?:^|[^A-Za-z0-9_./-])(?:(GET|POST|DELETE|PUT|PATCH) )?(/v1/[A-Za-z0-9_{}.-]+(?:/[A-Za-z0-9_{}.-]+)*|/healthz|/metrics)\b)");
  std::vector<DocRoute> out;
  for (const auto& file : files) {
    const std::string text = read(file);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), route);
         it != std::sregex_iterator(); ++it) {
      std::string path = (*it)[2];
      while (!path.empty() && path.back() == '.') path.pop_back();  // the end of a sentence
      out.push_back({file.filename().string(), (*it)[1], path});
    }
  }
  return out;
}

bool has_route(const std::string& method, const std::string& path) {
  const std::string route = matching_template(path);
  if (route.empty()) return false;
  if (method.empty()) return true;
  for (const ApiRoute& r : api_routes())
    if (r.path == route && r.method == method) return true;
  return false;
}

TEST(DocRoutes, EveryRouteNamedInTheDocsExists) {
  const std::vector<DocRoute> routes = documented_routes();
  ASSERT_GT(routes.size(), 20u) << "the docs name the API's routes; did the pattern break?";
  for (const auto& r : routes)
    EXPECT_TRUE(has_route(r.method, r.path))
        << r.file << " names " << (r.method.empty() ? "" : r.method + " ") << r.path
        << ", which the route table (service/api_routes.cpp) does not have";
}

TEST(DocRoutes, TheCheckFindsAMissingRoute) {
  EXPECT_FALSE(has_route("GET", "/v1/jobs/{id}/vtu"));
  EXPECT_FALSE(has_route("DELETE", "/v1/openapi.json"));
  EXPECT_TRUE(has_route("GET", "/v1/jobs/7/solution.vtu"));
  EXPECT_TRUE(has_route("", "/v1/jobs/{id}"));
}

}  // namespace
}  // namespace fosls::service
