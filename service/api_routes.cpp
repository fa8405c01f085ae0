#include "api_routes.hpp"

#include "http_api.hpp"
#include "job.hpp"
#include "openapi_builders.hpp"

namespace fosls::service {

namespace {

using nlohmann::json;
using namespace openapi;

const json kJob = json_body(ref("Job"), "the job");

/// A case of either format: 2D, or 3D with "dimension": 3.
json any_case() {
  return {{"description", "a 2D case, or a 3D case (\"dimension\": 3)"},
          {"anyOf", {{{"$ref", kCaseSchema}}, {{"$ref", kCase3dSchema}}}}};
}

json submit_job() {
  json op = operation(
      "submitJob", "Queue a case",
      responses({{"202", kJob}, {"200", json_body(ref("Job"), "replayed: the job of this key")}},
                {{400, "not JSON, or a bad Idempotency-Key"},
                 {411, "chunked, or no Content-Length"},
                 {413, "body above --max-body-bytes"},
                 {415, "Content-Type is not application/json"},
                 {422, "invalid case (errors lists every pointer), or key reused"},
                 {503, "queue full or store unavailable"},
                 {507, "the store's disk is full"}}),
      false);
  op["requestBody"] = {{"required", true},
                       {"content", {{"application/json", {{"schema", any_case()}}}}}};
  op["parameters"] = {{{"name", "Idempotency-Key"},
                       {"in", "header"},
                       {"required", false},
                       {"schema", {{"type", "string"}}}}};
  return op;
}

json list_jobs() {
  json list = {{"type", "object"},
               {"required", {"jobs", "next_page_token"}},
               {"properties",
                {{"jobs", {{"type", "array"}, {"items", ref("Job")}}},
                 {"next_page_token", nullable({{"type", "string"}})}}}};
  json op = operation(
      "listJobs", "List jobs, newest first",
      responses({{"200", json_body(list, "a page of jobs")}}, {{400, "a bad query parameter"}}),
      false);
  op["parameters"] = {
      {{"name", "state"}, {"in", "query"}, {"schema", job_json_schema()["properties"]["state"]}},
      {{"name", "converged"},
       {"in", "query"},
       {"description", "only jobs whose solve did (true) or did not (false) converge"},
       {"schema", {{"type", "boolean"}}}},
      {{"name", "page_size"},
       {"in", "query"},
       {"schema", {{"type", "integer"}, {"minimum", 1}, {"maximum", 100}, {"default", 20}}}},
      {{"name", "page_token"}, {"in", "query"}, {"schema", {{"type", "string"}}}}};
  return op;
}

json health() {
  json health = {{"type", "object"},
                 {"required", {"status", "workers", "busy"}},
                 {"properties",
                  {{"status", {{"const", "ok"}}},
                   {"workers", {{"type", "integer"}}},
                   {"busy", {{"type", "integer"}}}}}};
  return operation("health", "Liveness and the store",
                   responses({{"200", json_body(health, "healthy")}},
                             {{503, "store unavailable, or its disk is full (type store-full)"}}),
                   false);
}

json schema_document(const char* id, const char* summary) {
  return operation(id, summary,
                   {{"200", json_body({{"type", "object"}}, "JSON Schema draft 2020-12")}}, false);
}

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

// The table is a function-local static: HttpApi lets this function name its private handlers.
std::span<const ApiRoute> api_routes() {
  static const ApiRoute routes[] = {
      {"GET", "/v1/jobs", &HttpApi::list_jobs, list_jobs},
      {"POST", "/v1/jobs", &HttpApi::post_job, submit_job},
      {"GET", "/v1/jobs/{id}", &HttpApi::get_job,
       [] {
         return operation("getJob", "A job", responses({{"200", kJob}}, {{404, "no such job"}}),
                          true);
       }},
      {"DELETE", "/v1/jobs/{id}", &HttpApi::delete_job,
       [] {
         return operation("deleteJob", "Delete a finished job and its result",
                          responses({{"204", {{"description", "deleted"}}}},
                                    {{404, "no such job"}, {409, "queued or running"}}),
                          true);
       }},
      {"GET", "/v1/jobs/{id}/result", &HttpApi::get_result,
       [] {
         return operation(
             "getResult", "The result JSON (docs/result-format.md)",
             responses(
                 {{"200",
                   json_body({{"description", "a 2D case's result, or a 3D case's"},
                              {"anyOf", {{{"$ref", kResultSchema}}, {{"$ref", kResult3dSchema}}}}},
                             "the result")}},
                 {{404, "no such job"}, {409, "not finished, failed or cancelled"}}),
             true);
       }},
      {"GET", "/v1/jobs/{id}/solution.vtu", &HttpApi::get_solution,
       [] {
         return operation(
             "getSolution", "The VTU file for ParaView",
             responses({{"200",
                         {{"description", "VTK XML unstructured grid"},
                          {"content", {{"application/xml", {{"schema", {{"type", "string"}}}}}}}}}},
                       {{404, "no such job"}, {409, "not finished, failed or cancelled"}}),
             true);
       }},
      {"GET", "/v1/jobs/{id}/case", &HttpApi::get_case,
       [] {
         return operation(
             "getCase", "The case as submitted (canonical JSON: keys sorted)",
             responses({{"200", json_body(any_case(), "the case")}}, {{404, "no such job"}}), true);
       }},
      {"POST", "/v1/jobs/{id}/cancel", &HttpApi::cancel_job,
       [] {
         return operation("cancelJob", "Cancel a queued or running job",
                          responses({{"200", json_body(ref("Job"), "a queued job, now cancelled")},
                                     {"202", json_body(ref("Job"), "a running job, stopping")}},
                                    {{404, "no such job"}, {409, "already finished"}}),
                          true);
       }},
      {"GET", "/v1/openapi.json", &HttpApi::get_contract,
       [] {
         return operation("openapi", "This document",
                          {{"200", json_body({{"type", "object"}}, "OpenAPI 3.1")}}, false);
       }},
      {"GET", "/v1/schemas/case.json", &HttpApi::get_contract,
       [] {
         return schema_document("caseSchema",
                                "JSON Schema of a case (docs/schemas/case.schema.json)");
       }},
      {"GET", "/v1/schemas/case3d.json", &HttpApi::get_contract,
       [] {
         return schema_document("case3dSchema",
                                "JSON Schema of a 3D case (docs/schemas/case3d.schema.json)");
       }},
      {"GET", "/v1/schemas/result3d.json", &HttpApi::get_contract,
       [] {
         return schema_document(
             "result3dSchema",
             "JSON Schema of a 3D case's result (docs/schemas/result3d.schema.json)");
       }},
      {"GET", "/v1/schemas/result.json", &HttpApi::get_contract,
       [] {
         return schema_document("resultSchema",
                                "JSON Schema of a result (docs/schemas/result.schema.json)");
       }},
      {"GET", "/healthz", &HttpApi::healthz, health},
      {"GET", "/metrics", &HttpApi::metrics,
       [] {
         return operation("metrics", "Prometheus text exposition",
                          {{"200",
                            {{"description", "metrics"},
                             {"content", {{"text/plain", {{"schema", {{"type", "string"}}}}}}}}}},
                          false);
       }},
  };
  return routes;
}

std::string matching_template(std::string_view path) {
  for (const ApiRoute& r : api_routes())
    if (matches(r.path, path)) return std::string(r.path);
  return "";
}

std::string allowed_methods(std::string_view path) {
  const std::string route = matching_template(path);
  std::string methods;
  if (route.empty()) return methods;
  for (const ApiRoute& r : api_routes())
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
