#include "problem.hpp"

namespace fosls::service {

std::string_view reason_phrase(int status) {
  switch (status) {
    case 400:
      return "Bad Request";
    case 404:
      return "Not Found";
    case 405:
      return "Method Not Allowed";
    case 408:
      return "Request Timeout";
    case 409:
      return "Conflict";
    case 411:
      return "Length Required";
    case 413:
      return "Content Too Large";
    case 414:
      return "URI Too Long";
    case 415:
      return "Unsupported Media Type";
    case 422:
      return "Unprocessable Content";
    case 431:
      return "Request Header Fields Too Large";
    case 500:
      return "Internal Server Error";
    case 503:
      return "Service Unavailable";
    case 507:
      return "Insufficient Storage";
    default:
      return status >= 500 ? "Server Error" : "Client Error";
  }
}

nlohmann::json problem_to_json(const Problem& problem, std::string_view instance) {
  nlohmann::json j = {
      {"type", problem.type},
      {"title", problem.title.empty() ? std::string(reason_phrase(problem.status)) : problem.title},
      {"status", problem.status},
      {"detail", problem.detail},
      {"instance", std::string(instance)},
  };
  if (!problem.errors.empty()) {
    nlohmann::json errors = nlohmann::json::array();
    for (const CaseError& e : problem.errors) {
      errors.push_back({{"pointer", e.pointer}, {"detail", e.detail}});
    }
    j["errors"] = std::move(errors);
  }
  for (const auto& [key, value] : problem.extra.items()) j[key] = value;
  return j;
}

void send_problem(const httplib::Request& req, httplib::Response& res, const Problem& problem) {
  res.status = problem.status;
  res.set_content(problem_to_json(problem, req.path)
                      .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                  "application/problem+json");
}

}  // namespace fosls::service
