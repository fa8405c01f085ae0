#pragma once
// The machine-readable contract of the HTTP API: an OpenAPI 3.1 document (GET
// /v1/openapi.json) whose case and result bodies are the JSON Schemas generated from the rules
// the reader checks (docs/schemas, served at /v1/schemas/case.json and
// /v1/schemas/result.json), so the document cannot drift from validation. docs/service.md,
// "API", is the same contract for people.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace fosls::service {

/// The OpenAPI 3.1 document of the job service.
nlohmann::json openapi_document();

/// The JSON Schema served at /v1/schemas/<name> ("case.json", "result.json"); nothing for
/// another name.
std::optional<nlohmann::json> published_schema(const std::string& name);

}  // namespace fosls::service
