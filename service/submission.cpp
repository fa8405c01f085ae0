#include "submission.hpp"

#include "json_duplicates.hpp"
#include "problem_catalogue.hpp"
#include "request_checks.hpp"

namespace fosls::service {

namespace {

/// nlohmann's message for unparsable text (where and why); only called on the error path.
std::string parse_error_message(const std::string& text) {
  try {
    [[maybe_unused]] const auto j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for 1e999
    return e.what();
  }
  return "unknown parse error";
}

}  // namespace

std::variant<Problem, NewJob> read_submission(const std::string& body,
                                              const CaseValidator& validator, int max_json_depth) {
  if (json_nesting_depth(body, max_json_depth) > max_json_depth)
    return problems::unparsable_json("the JSON is nested deeper than " +
                                     std::to_string(max_json_depth) + " levels");
  nlohmann::json case_json = nlohmann::json::parse(body, nullptr, false);
  if (case_json.is_discarded())
    return problems::unparsable_json("the body is not valid JSON: " + parse_error_message(body));
  if (auto pointer = first_duplicate_key(body))
    return problems::invalid_case({{*pointer,
                                    "this key appears twice in its object; give each key once "
                                    "(JSON parsers disagree on which one counts)"}});
  CaseVerdict verdict = validator(case_json);
  if (!verdict.errors.empty()) return problems::invalid_case(std::move(verdict.errors));
  NewJob job;
  job.time_estimate_seconds = verdict.estimate_seconds;
  job.name = case_json.contains("name") && case_json["name"].is_string()
                 ? case_json["name"].get<std::string>()
                 : "case";
  job.case_json = case_json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  job.body_hash = sha256_hex(job.case_json);  // of the canonical text: keys sorted, no spaces
  return job;
}

}  // namespace fosls::service
