#pragma once
// Test double for the solver step: behaves as the case JSON says ("mode"), so store, worker
// and HTTP tests run without the solver library.
//
//   {"mode": "ok", "iterations": N}   reports N iterations, succeeds with {"echo": case}
//   {"mode": "ok", "converged": false} the same, a result that says it did not converge
//   {"mode": "fail"}                  fails with a message
//   {"mode": "throw"}                 throws std::runtime_error
//   {"mode": "throw_other"}           throws an int
//   {"mode": "until_cancel"}          iterates until cancelled

#include <chrono>
#include <stdexcept>
#include <thread>

#include "job_runner.hpp"

namespace fosls::service::testing {

inline JobRunOutcome fake_job_runner(const nlohmann::json& case_json,
                                     const JobRunContext& context) {
  const std::string mode = case_json.value("mode", "ok");
  JobRunOutcome out;
  if (mode == "throw") throw std::runtime_error("boom from the fake solver");
  if (mode == "throw_other") throw 42;
  if (mode == "fail") {
    out.kind = JobRunOutcome::Kind::kFailed;
    out.error = "/solver/tolerance: fake failure";
    return out;
  }
  if (mode == "until_cancel") {
    for (int i = 1; !context.cancel.load(); ++i) {
      context.report_progress(JobProgress{i, 1.0 / i, -1.0});
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    out.kind = JobRunOutcome::Kind::kCancelled;
    return out;
  }
  const int iterations = case_json.value("iterations", 3);
  for (int i = 1; i <= iterations; ++i) {
    if (context.cancel.load()) {
      out.kind = JobRunOutcome::Kind::kCancelled;
      return out;
    }
    context.report_progress(JobProgress{i, 1.0 / i, -static_cast<double>(i)});
  }
  out.kind = JobRunOutcome::Kind::kSucceeded;
  const bool converged = case_json.value("converged", true);
  out.result_json = nlohmann::json({{"echo", case_json},
                                    {"iterations", iterations},
                                    {"converged", converged},
                                    {"stop_reason", converged ? "converged" : "max_iterations"}})
                        .dump();
  out.vtu = "<VTKFile type=\"UnstructuredGrid\"/>";
  return out;
}

}  // namespace fosls::service::testing
