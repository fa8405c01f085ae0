#pragma once
// The routes of the HTTP API as one table (docs/service.md, "API"): each entry is a method, a
// path template, its handler in HttpApi and its OpenAPI operation, side by side. The server
// registers exactly these (HttpApi::install), 405 answers and metrics labels are derived from
// them, and the OpenAPI document is built from them (openapi.cpp). A new route touches three
// files: its entry in the table (api_routes.cpp) and its handler in HttpApi (http_api.hpp,
// http_api.cpp; docs/architecture.md, "Where to add").

#include <httplib.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace fosls::service {

class HttpApi;

struct ApiRoute {
  using PlainHandler = void (HttpApi::*)(const httplib::Request&, httplib::Response&);
  /// For templates with "{id}": called with the job id parsed from the path (a path whose
  /// segment is not a job id is answered 404 before).
  using JobHandler = void (HttpApi::*)(const httplib::Request&, httplib::Response&,
                                       std::int64_t job_id);

  std::string_view method;  ///< "GET", "POST" or "DELETE"
  std::string_view path;    ///< template; "{id}" stands for one path segment
  std::variant<PlainHandler, JobHandler> handler;
  nlohmann::json (*operation)();  ///< its OpenAPI 3.1 operation object
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
