#pragma once
// A submitted body read into the job to queue, or the problem that refuses it: nesting depth,
// JSON syntax, keys given twice, then the case's own validation (admission). The CPU-heavy part
// of POST /v1/jobs, kept apart so that large bodies can run it off the HTTP threads
// (admission_pool.hpp).

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "case_verdict.hpp"
#include "job_store.hpp"
#include "problem.hpp"

namespace fosls::service {

/// The job (name, canonical case JSON and its hash; no idempotency key) or the problem.
std::variant<Problem, NewJob> read_submission(const std::string& body,
                                              const CaseValidator& validator, int max_json_depth);

}  // namespace fosls::service
