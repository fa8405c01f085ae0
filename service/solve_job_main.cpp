// fosls-solve-job: solves one job's case in a process of its own, started by the service's
// workers (process_job_runner.hpp) under the job's memory limit, and killed by them on cancel
// or shutdown. A solve that runs out of memory or crashes ends this process only; its memory
// goes back to the system when it exits. Not meant to be run by hand.
//
// stdin: the case JSON. stdout: job_process_protocol.hpp. Exit code 3: out of memory (also
// said on stderr). `--max-job-memory BYTES`: the budget the case was admitted against, checked
// again on the coarse mesh once it is built.

#include <atomic>
#include <cerrno>
#include <iostream>
#include <iterator>
#include <new>
#include <string>

#include "case_job_runner.hpp"
#include "job_process_protocol.hpp"
#include "process/child_process.hpp"
#include "process/malloc_arenas.hpp"
#include "process/solver_environment.hpp"

int main(int argc, char** argv) {
  using namespace fosls::service;
  // Sleeping OpenMP waiters and huge pages for malloc's large blocks (solver_environment.hpp);
  // before anything reads stdin: the restarted program reads the case.
  fosls::restart_with_solver_environment(argv);
  fosls::die_with_parent();
  fosls::use_one_malloc_arena();
  fosls::keep_freed_memory();
  // Nothing a library prints can corrupt the answer: fd 1 now writes to stderr.
  const int protocol_fd = fosls::take_stdout_for_answer();
  try {
    const std::string text{std::istreambuf_iterator<char>(std::cin),
                           std::istreambuf_iterator<char>()};
    const nlohmann::json case_json = nlohmann::json::parse(text);
    // Cancel and shutdown kill this process; nothing inside needs to look at a flag.
    const std::atomic<bool> never{false};
    JobRunContext context{never, [protocol_fd](const JobProgress& p) {
                            fosls::write_all(protocol_fd, progress_message(p));
                          }};
    // A cancel kills this process: what it would leave is sent as it is known.
    context.report_partial = [protocol_fd](const std::string& r) {
      fosls::write_all(protocol_fd, partial_message(r));
    };
    std::size_t job_memory_bytes = 0;
    for (int i = 1; i + 1 < argc; ++i)
      if (std::string(argv[i]) == "--max-job-memory") job_memory_bytes = std::stoull(argv[i + 1]);
    JobRunOutcome outcome;
    try {
      outcome = run_case_job(case_json, context, job_memory_bytes);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      outcome.kind = JobRunOutcome::Kind::kFailed;
      outcome.error = std::string("internal error while solving: ") + e.what();
    }
    return fosls::write_all(protocol_fd, outcome_message(outcome)) ? 0 : 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "fosls-solve-job: out of memory (std::bad_alloc)\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "fosls-solve-job: " << e.what() << '\n';
    return 1;
  }
}
