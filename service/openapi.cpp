#include "openapi.hpp"

#include <cctype>

#include "api_routes.hpp"
#include "case/format/published_formats.hpp"
#include "job.hpp"
#include "openapi_builders.hpp"

namespace fosls::service {

namespace {

using nlohmann::json;

using openapi::string_field;

json problem_schema() {
  json error = {{"type", "object"},
                {"required", {"pointer", "detail"}},
                {"properties",
                 {{"pointer", string_field("JSON pointer (RFC 6901) into the case")},
                  {"detail", string_field("what is wrong and how to fix it")}}}};
  return {{"type", "object"},
          {"description", "RFC 9457 problem details; type is urn:fosls:problem:<name>"},
          {"required", {"type", "title", "status", "detail"}},
          {"properties",
           {{"type", {{"type", "string"}}},
            {"title", {{"type", "string"}}},
            {"status", {{"type", "integer"}}},
            {"detail", {{"type", "string"}}},
            {"instance", {{"type", "string"}}},
            {"errors", {{"type", "array"}, {"items", error}}}}}};
}

}  // namespace

json openapi_document() {
  json paths = json::object();
  for (const ApiRoute& route : api_routes()) {
    std::string method(route.method);
    for (char& c : method) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    paths[std::string(route.path)][method] = route.operation();
  }
  return {
      {"openapi", "3.1.0"},
      {"info",
       {{"title", "fosls-contact job service"},
        {"version", "1"},
        {"description",
         "Queue 2D frictionless contact cases, poll their jobs, read results "
         "(docs/service.md). Case and result bodies are the JSON Schemas served under "
         "/v1/schemas, generated from the rules the service validates with."}}},
      {"jsonSchemaDialect", "https://json-schema.org/draft/2020-12/schema"},
      {"paths", std::move(paths)},
      {"components", {{"schemas", {{"Job", job_json_schema()}, {"Problem", problem_schema()}}}}}};
}

std::optional<json> published_schema(const std::string& name) {
  if (name == "case.json") return case_json_schema();
  if (name == "case3d.json") return case_json_schema();  // one schema for both dimensions
  if (name == "result.json") return result_json_schema();
  if (name == "result3d.json") return result3d_json_schema();
  return std::nullopt;
}

}  // namespace fosls::service
