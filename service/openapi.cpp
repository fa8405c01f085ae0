#include "openapi.hpp"

#include "case/published_formats.hpp"

namespace fosls::service {

namespace {

using nlohmann::json;

const std::string kCaseSchema = "/v1/schemas/case.json";
const std::string kResultSchema = "/v1/schemas/result.json";

json ref(const std::string& name) { return {{"$ref", "#/components/schemas/" + name}}; }

json nullable(json schema) {
  return {{"anyOf", json::array({std::move(schema), {{"type", "null"}}})}};
}

json string_field(const std::string& description) {
  return {{"type", "string"}, {"description", description}};
}

// The job resource (job.cpp, job_to_json); tests validate real jobs against it.
json job_schema() {
  json links = {{"type", "object"},
                {"additionalProperties", false},
                {"required", {"self", "result", "solution", "cancel", "case"}},
                {"properties",
                 {{"self", string_field("this job")},
                  {"result", string_field("its result JSON")},
                  {"solution", string_field("its VTU file")},
                  {"cancel", string_field("POST here to cancel it")},
                  {"case", string_field("the case as submitted")}}}};
  json progress = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"iteration", "kkt_residual", "energy"}},
      {"properties",
       {{"iteration", {{"type", "integer"}, {"minimum", 0}}},
        {"kkt_residual", nullable({{"type", "number"}})},
        {"energy", nullable({{"type", "number"}, {"description", "the scaled functional J"}})}}}};
  json time = {{"type", "string"}, {"format", "date-time"}};
  return {
      {"type", "object"},
      {"additionalProperties", false},
      {"required",
       {"id", "name", "state", "created_at", "started_at", "finished_at", "attempts",
        "cancel_requested", "progress", "error", "converged", "stop_reason", "links"}},
      {"properties",
       {{"id", {{"type", "integer"}, {"minimum", 1}}},
        {"name", string_field("the case's name")},
        {"state", {{"enum", {"queued", "running", "succeeded", "failed", "cancelled"}}}},
        {"created_at", time},
        {"started_at", nullable(time)},
        {"finished_at", nullable(time)},
        {"attempts", {{"type", "integer"}, {"minimum", 0}}},
        {"cancel_requested", {{"type", "boolean"}}},
        {"progress", nullable(progress)},
        {"error", nullable(string_field("why it failed, with JSON pointers for case problems"))},
        {"converged", nullable({{"type", "boolean"},
                                {"description",
                                 "the result's converged; null until a result is stored. A job can "
                                 "succeed without converging unless the service runs with "
                                 "--fail-unconverged"}})},
        {"stop_reason", nullable({{"$ref", kResultSchema + "#/properties/stop_reason"}})},
        {"links", links}}}};
}

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

json json_body(json schema, const std::string& description) {
  return {{"description", description},
          {"content", {{"application/json", {{"schema", std::move(schema)}}}}}};
}

/// Responses with problem bodies for each status in `errors`.
json responses(json ok, std::initializer_list<std::pair<int, const char*>> errors) {
  for (const auto& [status, why] : errors) {
    ok[std::to_string(status)] = {
        {"description", why},
        {"content", {{"application/problem+json", {{"schema", ref("Problem")}}}}}};
  }
  return ok;
}

json id_parameter() {
  return {{"name", "id"},
          {"in", "path"},
          {"required", true},
          {"schema", {{"type", "integer"}, {"minimum", 1}}}};
}

json operation(const std::string& id, const std::string& summary, json responses_json,
               bool takes_id = true) {
  json op = {{"operationId", id}, {"summary", summary}, {"responses", std::move(responses_json)}};
  if (takes_id) op["parameters"] = json::array({id_parameter()});
  return op;
}

json job_paths() {
  const json job = json_body(ref("Job"), "the job");
  json paths;
  paths["/v1/jobs"]["post"] = operation(
      "submitJob", "Queue a case",
      responses({{"202", job}, {"200", json_body(ref("Job"), "replayed: the job of this key")}},
                {{400, "not JSON, or a bad Idempotency-Key"},
                 {411, "chunked, or no Content-Length"},
                 {413, "body above --max-body-bytes"},
                 {415, "Content-Type is not application/json"},
                 {422, "invalid case (errors lists every pointer), or key reused"},
                 {503, "queue full or store unavailable"}}),
      false);
  paths["/v1/jobs"]["post"]["requestBody"] = {
      {"required", true},
      {"content", {{"application/json", {{"schema", {{"$ref", kCaseSchema}}}}}}}};
  paths["/v1/jobs"]["post"]["parameters"] = {{{"name", "Idempotency-Key"},
                                              {"in", "header"},
                                              {"required", false},
                                              {"schema", {{"type", "string"}}}}};
  json list = {{"type", "object"},
               {"required", {"jobs", "next_page_token"}},
               {"properties",
                {{"jobs", {{"type", "array"}, {"items", ref("Job")}}},
                 {"next_page_token", nullable({{"type", "string"}})}}}};
  paths["/v1/jobs"]["get"] = operation(
      "listJobs", "List jobs, newest first",
      responses({{"200", json_body(list, "a page of jobs")}}, {{400, "a bad query parameter"}}),
      false);
  paths["/v1/jobs"]["get"]["parameters"] = {
      {{"name", "state"}, {"in", "query"}, {"schema", job_schema()["properties"]["state"]}},
      {{"name", "converged"},
       {"in", "query"},
       {"description", "only jobs whose solve did (true) or did not (false) converge"},
       {"schema", {{"type", "boolean"}}}},
      {{"name", "page_size"},
       {"in", "query"},
       {"schema", {{"type", "integer"}, {"minimum", 1}, {"maximum", 100}, {"default", 20}}}},
      {{"name", "page_token"}, {"in", "query"}, {"schema", {{"type", "string"}}}}};
  paths["/v1/jobs/{id}"]["get"] =
      operation("getJob", "A job", responses({{"200", job}}, {{404, "no such job"}}));
  paths["/v1/jobs/{id}"]["delete"] =
      operation("deleteJob", "Delete a finished job and its result",
                responses({{"204", {{"description", "deleted"}}}},
                          {{404, "no such job"}, {409, "queued or running"}}));
  paths["/v1/jobs/{id}/result"]["get"] =
      operation("getResult", "The result JSON (docs/result-format.md)",
                responses({{"200", json_body({{"$ref", kResultSchema}}, "the result")}},
                          {{404, "no such job"}, {409, "not finished, failed or cancelled"}}));
  paths["/v1/jobs/{id}/solution.vtu"]["get"] = operation(
      "getSolution", "The VTU file for ParaView",
      responses({{"200",
                  {{"description", "VTK XML unstructured grid"},
                   {"content", {{"application/xml", {{"schema", {{"type", "string"}}}}}}}}}},
                {{404, "no such job"}, {409, "not finished, failed or cancelled"}}));
  paths["/v1/jobs/{id}/case"]["get"] = operation(
      "getCase", "The case as submitted (canonical JSON: keys sorted)",
      responses({{"200", json_body({{"$ref", kCaseSchema}}, "the case")}}, {{404, "no such job"}}));
  paths["/v1/jobs/{id}/cancel"]["post"] =
      operation("cancelJob", "Cancel a queued or running job",
                responses({{"200", json_body(ref("Job"), "a queued job, now cancelled")},
                           {"202", json_body(ref("Job"), "a running job, stopping")}},
                          {{404, "no such job"}, {409, "already finished"}}));
  return paths;
}

json service_paths() {
  json paths;
  json health = {{"type", "object"},
                 {"required", {"status", "workers", "busy"}},
                 {"properties",
                  {{"status", {{"const", "ok"}}},
                   {"workers", {{"type", "integer"}}},
                   {"busy", {{"type", "integer"}}}}}};
  paths["/healthz"]["get"] = operation(
      "health", "Liveness and the store",
      responses({{"200", json_body(health, "healthy")}}, {{503, "store unavailable"}}), false);
  paths["/metrics"]["get"] =
      operation("metrics", "Prometheus text exposition",
                {{"200",
                  {{"description", "metrics"},
                   {"content", {{"text/plain", {{"schema", {{"type", "string"}}}}}}}}}},
                false);
  paths["/v1/openapi.json"]["get"] = operation(
      "openapi", "This document", {{"200", json_body({{"type", "object"}}, "OpenAPI 3.1")}}, false);
  paths["/v1/schemas/case.json"]["get"] =
      operation("caseSchema", "JSON Schema of a case (docs/schemas/case.schema.json)",
                {{"200", json_body({{"type", "object"}}, "JSON Schema draft 2020-12")}}, false);
  paths["/v1/schemas/result.json"]["get"] =
      operation("resultSchema", "JSON Schema of a result (docs/schemas/result.schema.json)",
                {{"200", json_body({{"type", "object"}}, "JSON Schema draft 2020-12")}}, false);
  return paths;
}

}  // namespace

json openapi_document() {
  json paths = job_paths();
  paths.update(service_paths());
  return {{"openapi", "3.1.0"},
          {"info",
           {{"title", "fosls-contact job service"},
            {"version", "1"},
            {"description",
             "Queue 2D frictionless contact cases, poll their jobs, read results "
             "(docs/service.md). Case and result bodies are the JSON Schemas served under "
             "/v1/schemas, generated from the rules the service validates with."}}},
          {"jsonSchemaDialect", "https://json-schema.org/draft/2020-12/schema"},
          {"paths", std::move(paths)},
          {"components", {{"schemas", {{"Job", job_schema()}, {"Problem", problem_schema()}}}}}};
}

std::optional<json> published_schema(const std::string& name) {
  if (name == "case.json") return case_json_schema();
  if (name == "result.json") return result_json_schema();
  return std::nullopt;
}

}  // namespace fosls::service
