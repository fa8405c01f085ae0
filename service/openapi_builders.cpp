#include "openapi_builders.hpp"

namespace fosls::service::openapi {

using nlohmann::json;

json ref(const std::string& name) { return {{"$ref", "#/components/schemas/" + name}}; }

json nullable(json schema) {
  return {{"anyOf", json::array({std::move(schema), {{"type", "null"}}})}};
}

json string_field(const std::string& description) {
  return {{"type", "string"}, {"description", description}};
}

json json_body(json schema, const std::string& description) {
  return {{"description", description},
          {"content", {{"application/json", {{"schema", std::move(schema)}}}}}};
}

json responses(json ok, std::initializer_list<std::pair<int, const char*>> errors) {
  for (const auto& [status, why] : errors) {
    ok[std::to_string(status)] = {
        {"description", why},
        {"content", {{"application/problem+json", {{"schema", ref("Problem")}}}}}};
  }
  return ok;
}

json operation(const std::string& id, const std::string& summary, json responses_json,
               bool takes_id) {
  json op = {{"operationId", id}, {"summary", summary}, {"responses", std::move(responses_json)}};
  if (takes_id)
    op["parameters"] = json::array({{{"name", "id"},
                                     {"in", "path"},
                                     {"required", true},
                                     {"schema", {{"type", "integer"}, {"minimum", 1}}}}});
  return op;
}

}  // namespace fosls::service::openapi
