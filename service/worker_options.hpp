#pragma once
// What fosls-serve and fosls-worker share: the store and worker options, the job runner, and
// the stop signals. One definition each, so the two programs cannot drift apart.

#include <signal.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <string>

#include "job_runner.hpp"
#include "worker_pool.hpp"

namespace fosls::service {

/// --max-job-seconds when not given: one hour.
inline constexpr double kDefaultMaxJobSeconds = 3600;

/// Options of the solver workers and their store.
struct WorkerOptions {
  std::string store = "sqlite:data/fosls.db";  ///< --store URL (store_url.hpp)
  int workers = 1;
  int max_attempts = 3;
  double lease_seconds = 30;
  double heartbeat_seconds = 1;
  /// --max-job-memory as written ("2G"); empty: default_job_memory(workers).
  std::string max_job_memory;
  /// --max-job-seconds: the most wall-clock time one job may run (each job may run a margin
  /// times its estimate within it, case_job_runner.hpp); 0, given explicitly: no limit at all.
  double max_job_seconds = kDefaultMaxJobSeconds;
  /// --fail-unconverged: a solve that stops without converging fails its job.
  bool fail_unconverged = false;
  /// --admit-over-budget: cases estimated above --max-job-memory are queued and run anyway
  /// (under the limit), and not stopped when their mesh is built.
  bool admit_over_budget = false;

  /// The memory each job may use, in bytes.
  std::size_t job_memory_bytes() const;
  /// The budget cases are admitted against: job_memory_bytes(), or 0 (none) with
  /// --admit-over-budget.
  std::size_t admission_memory_bytes() const;

  /// The pool options these give (worker id generated per process).
  WorkerPoolOptions pool_options() const;
  /// How often this process looks for expired leases.
  std::chrono::milliseconds reaper_interval() const;
  /// Why these options cannot work together, or "" when they can.
  std::string problem() const;
};

/// Registers --store, --workers, --max-attempts, --lease-seconds, --heartbeat-seconds,
/// --max-job-memory, --max-job-seconds, --fail-unconverged and --admit-over-budget on `app`;
/// `min_workers` is 0 for fosls-serve (API only) and 1 for fosls-worker.
void add_worker_options(CLI::App& app, WorkerOptions& options, int min_workers);

/// The JobRunner both programs solve jobs with: each job in a fosls-solve-job process under
/// the job memory limit, with cores / workers threads.
JobRunner service_job_runner(const WorkerOptions& options);

/// Blocks SIGINT and SIGTERM in the calling thread and every thread started after it, so that
/// stop_signal_wait can take them as ordinary code; ignores SIGPIPE (a client closing early).
sigset_t block_stop_signals();

/// Waits for the first stop signal and returns its number. A second one then ends the process
/// at once (running jobs are recovered later: at the next start on SQLite, by lease expiry on
/// PostgreSQL).
int wait_for_stop_signal(const sigset_t& stop_signals);

}  // namespace fosls::service
