#pragma once
// Every kind of error response of the API, built in one place: its status, its type
// (urn:fosls:problem:NAME, listed in docs/service.md) and a detail that says what to change.
// Handlers pick one; none builds a Problem by hand.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "case/format/case_error.hpp"
#include "job.hpp"
#include "problem.hpp"

namespace fosls::service::problems {

Problem unparsable_json(const std::string& detail);                             // 400
Problem invalid_content_length(const std::string& why);                         // 400
Problem invalid_idempotency_key();                                              // 400
Problem invalid_parameter(const std::string& name, const std::string& detail);  // 400
Problem bad_request(const std::string& detail);                                 // 400, about:blank
Problem not_found(const std::string& detail);                                   // 404, about:blank
Problem job_not_found(std::int64_t id);                                         // 404
Problem method_not_allowed(const std::string& method, const std::string& path,
                           const std::string& allowed);  // 405
/// 409 for the result or VTU of a job that has none (yet or ever).
Problem job_without_result(const Job& job);
Problem job_finished(std::int64_t id, JobState state);  // 409, cancel
Problem job_not_finished(std::int64_t id);              // 409, delete
Problem length_required(const std::string& why);        // 411
Problem payload_too_large(std::size_t limit);           // 413
Problem uri_too_long();                                 // 414
/// A request head refused while it was read (bounded_http_server.hpp): 400 malformed, 408 too
/// slow, 414 request line too long, 431 header fields too large or too many.
Problem refused_request_head(int status, const std::string& detail);
Problem unsupported_media_type(const std::string& got);  // 415
Problem invalid_case(std::vector<CaseError> errors);     // 422
Problem idempotency_key_reused(std::int64_t job_id);     // 422
Problem internal_error();                                // 500
Problem queue_full(std::size_t max_queue);               // 503
Problem store_unavailable();                             // 503
Problem admission_busy();                                // 503: large submissions queued
/// The store's disk is full: 507 for a request that had to write, 503 for GET /healthz.
Problem store_full(int status, const std::string& store_message);

}  // namespace fosls::service::problems
