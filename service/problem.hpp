#pragma once
// Error responses as RFC 9457 problem details (application/problem+json).

#include <httplib.h>

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "case/format/case_error.hpp"

namespace fosls::service {

/// One problem detail document. `type` is a URN naming the kind of problem
/// ("about:blank" when the status code says it all).
struct Problem {
  int status = 500;
  std::string type = "about:blank";
  std::string title;              ///< defaults to the status' reason phrase
  std::string detail;             ///< this occurrence, for a person
  std::vector<CaseError> errors;  ///< validation errors: JSON pointer into the body + reason
  nlohmann::json extra = nlohmann::json::object();  ///< further members (e.g. "job")
};

/// The HTTP reason phrase of a status code ("Unprocessable Content" for 422).
std::string_view reason_phrase(int status);

/// The problem as JSON.
nlohmann::json problem_to_json(const Problem& problem, std::string_view instance);

/// Sets status, Content-Type and body of `res`.
void send_problem(const httplib::Request& req, httplib::Response& res, const Problem& problem);

}  // namespace fosls::service
