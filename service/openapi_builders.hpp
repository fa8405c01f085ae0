#pragma once
// Building blocks of the OpenAPI document (openapi.hpp): the route table (api_routes.cpp)
// writes each route's operation with them, the job resource (job.cpp) its schema.

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

namespace fosls::service::openapi {

/// Where the case and result JSON Schemas are served (and $ref'd from).
inline const std::string kCaseSchema = "/v1/schemas/case.json";
inline const std::string kCase3dSchema = "/v1/schemas/case3d.json";
inline const std::string kResultSchema = "/v1/schemas/result.json";
inline const std::string kResult3dSchema = "/v1/schemas/result3d.json";

/// {"$ref": "#/components/schemas/NAME"}.
nlohmann::json ref(const std::string& name);
/// `schema` or null.
nlohmann::json nullable(nlohmann::json schema);
nlohmann::json string_field(const std::string& description);
/// A response or request body of JSON with `schema`.
nlohmann::json json_body(nlohmann::json schema, const std::string& description);
/// `ok` plus a problem+json response for each status in `errors`.
nlohmann::json responses(nlohmann::json ok,
                         std::initializer_list<std::pair<int, const char*>> errors);
/// An operation; `takes_id`: its path has the job id parameter {id}.
nlohmann::json operation(const std::string& id, const std::string& summary,
                         nlohmann::json responses_json, bool takes_id);

}  // namespace fosls::service::openapi
