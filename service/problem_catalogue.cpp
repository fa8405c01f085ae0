#include "problem_catalogue.hpp"

namespace fosls::service::problems {

namespace {

Problem make(int status, const char* name, std::string detail) {
  Problem p;
  p.status = status;
  if (name) p.type = std::string("urn:fosls:problem:") + name;
  p.detail = std::move(detail);
  return p;
}

}  // namespace

Problem unparsable_json(const std::string& detail) { return make(400, "unparsable-json", detail); }

Problem invalid_content_length(const std::string& why) {
  return make(400, "invalid-content-length", why);
}

Problem invalid_idempotency_key() {
  return make(400, "invalid-idempotency-key",
              "Idempotency-Key must be 1 to 255 visible ASCII characters");
}

Problem invalid_parameter(const std::string& name, const std::string& detail) {
  Problem p = make(400, "invalid-parameter", "query parameter '" + name + "': " + detail);
  p.extra["errors"] = nlohmann::json::array({{{"parameter", name}, {"detail", detail}}});
  return p;
}

Problem bad_request(const std::string& detail) { return make(400, nullptr, detail); }

Problem not_found(const std::string& detail) { return make(404, nullptr, detail); }

Problem job_not_found(std::int64_t id) {
  return make(404, "job-not-found",
              "there is no job " + std::to_string(id) + " (it may have been deleted)");
}

Problem method_not_allowed(const std::string& method, const std::string& path,
                           const std::string& allowed) {
  return make(405, nullptr,
              method + " is not supported on " + path + " (allowed: " + allowed + ")");
}

Problem job_without_result(const Job& job) {
  const std::string which = "job " + std::to_string(job.id);
  Problem p;
  switch (job.state) {
    case JobState::kQueued:
    case JobState::kRunning:
      p = make(409, "job-not-finished",
               which + " is " + std::string(to_string(job.state)) + "; poll /v1/jobs/" +
                   std::to_string(job.id) + " until its state is succeeded");
      break;
    case JobState::kFailed:
      p = make(409, "job-failed", which + " failed: " + job.error);
      break;
    case JobState::kCancelled:
      p = make(409, "job-cancelled",
               which +
                   " was cancelled before it had a result to keep (a job with load steps keeps "
                   "the steps solved before a cancel)");
      break;
    case JobState::kSucceeded:
      p = make(500, nullptr, which + " succeeded but its result is missing");
      break;
  }
  p.extra["state"] = std::string(to_string(job.state));
  return p;
}

Problem job_finished(std::int64_t id, JobState state) {
  Problem p = make(409, "job-finished",
                   "job " + std::to_string(id) + " is already " + std::string(to_string(state)) +
                       "; there is nothing to cancel");
  p.extra["state"] = std::string(to_string(state));
  return p;
}

Problem job_not_finished(std::int64_t id) {
  return make(
      409, "job-not-finished",
      "job " + std::to_string(id) + " is still queued or running; cancel it first, then delete it");
}

Problem length_required(const std::string& why) { return make(411, "length-required", why); }

Problem payload_too_large(std::size_t limit) {
  return make(413, "payload-too-large",
              "the request body is larger than the limit of " + std::to_string(limit) + " bytes");
}

Problem uri_too_long() { return make(414, nullptr, "the request URI is too long"); }

Problem refused_request_head(int status, const std::string& detail) {
  switch (status) {
    case 400:
      return make(400, "malformed-request-head", detail);
    case 408:
      return make(408, "request-head-timeout", detail);
    case 431:
      return make(431, "header-fields-too-large", detail);
    default:
      return make(status, nullptr, detail);
  }
}

Problem unsupported_media_type(const std::string& got) {
  return make(415, "unsupported-media-type",
              "send the case with 'Content-Type: application/json' (got '" +
                  (got.empty() ? std::string("none") : got) + "')");
}

Problem invalid_case(std::vector<CaseError> errors) {
  Problem p = make(422, "invalid-case",
                   std::to_string(errors.size()) + (errors.size() == 1 ? " problem" : " problems") +
                       " in the case; each entry of errors names the field (JSON pointer) and "
                       "the fix");
  p.title = "The case is not valid";
  p.errors = std::move(errors);
  return p;
}

Problem idempotency_key_reused(std::int64_t job_id) {
  Problem p = make(422, "idempotency-key-reused",
                   "this Idempotency-Key was already used for job " + std::to_string(job_id) +
                       " with a different body; use a new key for a new case");
  p.extra["job"] = "/v1/jobs/" + std::to_string(job_id);
  return p;
}

Problem internal_error() {
  return make(500, nullptr, "internal error; the request was not completed");
}

Problem queue_full(std::size_t max_queue) {
  return make(
      503, "queue-full",
      "the queue already holds " + std::to_string(max_queue) + " waiting jobs; retry later");
}

Problem store_full(int status, const std::string& store_message) {
  Problem p = make(status, "store-full",
                   "the job store's disk is full: jobs cannot be queued, started or finished "
                   "until space is freed on it; retry later (the store said: " +
                       store_message + ")");
  p.title = "The job store's disk is full";
  return p;
}

Problem admission_busy() {
  return make(503, "admission-busy",
              "too many large submissions are waiting to be checked; retry later");
}

Problem store_unavailable() {
  return make(503, "store-unavailable", "the job store is busy or unavailable; retry later");
}

}  // namespace fosls::service::problems
