#include "api_routes.hpp"

#include <array>

namespace fosls::service {

namespace {

constexpr std::array kRoutes = {
    ApiRoute{"GET", "/v1/jobs"},
    ApiRoute{"POST", "/v1/jobs"},
    ApiRoute{"GET", "/v1/jobs/{id}"},
    ApiRoute{"DELETE", "/v1/jobs/{id}"},
    ApiRoute{"GET", "/v1/jobs/{id}/result"},
    ApiRoute{"GET", "/v1/jobs/{id}/solution.vtu"},
    ApiRoute{"GET", "/v1/jobs/{id}/case"},
    ApiRoute{"POST", "/v1/jobs/{id}/cancel"},
    ApiRoute{"GET", "/v1/openapi.json"},
    ApiRoute{"GET", "/v1/schemas/case.json"},
    ApiRoute{"GET", "/v1/schemas/result.json"},
    ApiRoute{"GET", "/healthz"},
    ApiRoute{"GET", "/metrics"},
};

constexpr std::string_view kId = "{id}";

/// Whether `path` has the shape of `pattern`: equal text, except that {id} takes one
/// non-empty segment.
bool matches(std::string_view pattern, std::string_view path) {
  const auto id = pattern.find(kId);
  if (id == std::string_view::npos) return pattern == path;
  const std::string_view head = pattern.substr(0, id), tail = pattern.substr(id + kId.size());
  if (path.size() <= head.size() + tail.size() || path.substr(0, head.size()) != head ||
      path.substr(path.size() - tail.size()) != tail)
    return false;
  const std::string_view segment =
      path.substr(head.size(), path.size() - head.size() - tail.size());
  return segment.find('/') == std::string_view::npos;
}

}  // namespace

std::span<const ApiRoute> api_routes() { return kRoutes; }

std::string matching_template(std::string_view path) {
  for (const ApiRoute& r : kRoutes)
    if (matches(r.path, path)) return std::string(r.path);
  return "";
}

std::string allowed_methods(std::string_view path) {
  const std::string route = matching_template(path);
  std::string methods;
  if (route.empty()) return methods;
  for (const ApiRoute& r : kRoutes)
    if (r.path == route) methods += (methods.empty() ? "" : ", ") + std::string(r.method);
  return methods;
}

std::string id_segment(std::string_view pattern, std::string_view path) {
  const auto id = pattern.find(kId);
  if (id == std::string_view::npos || !matches(pattern, path)) return "";
  const std::size_t tail = pattern.size() - id - kId.size();
  return std::string(path.substr(id, path.size() - id - tail));
}

std::string route_pattern(std::string_view path) {
  std::string pattern;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path.substr(i, kId.size()) == kId) {
      pattern += "([^/]+)";
      i += kId.size() - 1;
    } else {
      pattern += path[i] == '.' ? std::string("\\.") : std::string(1, path[i]);
    }
  }
  return pattern;
}

}  // namespace fosls::service
