#pragma once
// The routes of the HTTP API as one table (docs/service.md, "API"): the server registers
// exactly these (HttpApi::install), 405 answers and metrics labels are derived from them, and
// the OpenAPI document lists exactly these (tested), so a new route is added in one place.

#include <span>
#include <string>
#include <string_view>

namespace fosls::service {

struct ApiRoute {
  std::string_view method;  ///< "GET", "POST" or "DELETE"
  std::string_view path;    ///< template; "{id}" stands for one path segment
};

std::span<const ApiRoute> api_routes();

/// The template that `path` matches ("/v1/jobs/17/result" → "/v1/jobs/{id}/result"), or ""
/// when no route has it.
std::string matching_template(std::string_view path);

/// "GET, DELETE": the methods of the routes with the template `path` matches ("" for none), in
/// table order, for the Allow header of 405 answers.
std::string allowed_methods(std::string_view path);

/// The segment of `path` that stands for "{id}" in the template `pattern` ("" if none).
std::string id_segment(std::string_view pattern, std::string_view path);

/// The cpp-httplib pattern (a regular expression) of a template: "{id}" captures one segment,
/// "." is literal.
std::string route_pattern(std::string_view path);

}  // namespace fosls::service
