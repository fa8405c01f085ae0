#include "worker_options.hpp"

#include <pthread.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "memory_budget.hpp"
#include "process_job_runner.hpp"

namespace fosls::service {

namespace {
std::chrono::milliseconds seconds_to_ms(double seconds) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(seconds * 1000.0));
}
}  // namespace

WorkerPoolOptions WorkerOptions::pool_options() const {
  WorkerPoolOptions o;
  o.workers = workers;
  o.lease_duration = seconds_to_ms(lease_seconds);
  o.heartbeat_interval = seconds_to_ms(heartbeat_seconds);
  o.fail_unconverged = fail_unconverged;
  o.declared_job_memory = job_memory_bytes();
  return o;
}

std::size_t WorkerOptions::job_memory_bytes() const {
  if (auto bytes = parse_byte_size(max_job_memory)) return *bytes;
  return default_job_memory(workers);
}

std::size_t WorkerOptions::admission_memory_bytes() const {
  return admit_over_budget ? 0 : job_memory_bytes();
}

std::chrono::milliseconds WorkerOptions::reaper_interval() const {
  // Often enough that a dead worker's job waits little beyond its lease.
  return std::clamp(seconds_to_ms(lease_seconds / 4), std::chrono::milliseconds(200),
                    std::chrono::milliseconds(10000));
}

std::string WorkerOptions::problem() const {
  // A lease must survive a late heartbeat or two, or healthy workers lose their jobs.
  if (heartbeat_seconds * 3 > lease_seconds) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "--heartbeat-seconds %g is too long for --lease-seconds %g: a lease must last "
                  "at least three heartbeats",
                  heartbeat_seconds, lease_seconds);
    return text;
  }
  return "";
}

void add_worker_options(CLI::App& app, WorkerOptions& o, int min_workers) {
  app.add_option("--store", o.store,
                 "Job store: sqlite:PATH (one process) or postgresql://USER:PASSWORD@HOST:PORT/DB "
                 "(shared by several processes)")
      ->capture_default_str();
  app.add_option("--workers", o.workers,
                 min_workers == 0 ? "Solver threads (0: API only; default: hardware cores)"
                                  : "Solver threads (default: hardware cores)")
      ->check(CLI::Range(min_workers, 256))
      ->capture_default_str();
  app.add_option("--max-attempts", o.max_attempts,
                 "Starts after which a job whose worker died is failed, not retried")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  app.add_option("--lease-seconds", o.lease_seconds,
                 "A running job whose worker stopped renewing its lease this long is re-queued")
      ->check(CLI::Range(0.5, 86400.0))
      ->capture_default_str();
  app.add_option("--heartbeat-seconds", o.heartbeat_seconds,
                 "How often running jobs renew their lease and look for cancels")
      ->check(CLI::Range(0.05, 3600.0))
      ->capture_default_str();
  app.add_option("--max-job-memory", o.max_job_memory,
                 "Memory one job may use, e.g. 512M or 2G (default: 3/4 of RAM / workers); cases "
                 "estimated above it are refused, a solve that exceeds it fails its job")
      ->check([](const std::string& text) {
        return parse_byte_size(text) ? std::string()
                                     : "expected a size such as 512M or 2G, got '" + text + "'";
      });
  app.add_option("--max-job-seconds", o.max_job_seconds,
                 "The most wall-clock time one job may run (0: no limit at all): cases estimated "
                 "above it are refused; each job may run 10 times its estimate, at least 60 s, "
                 "at most this, and is then killed and fails")
      ->check(CLI::Range(0.0, 1e7))
      ->capture_default_str();
  app.add_flag("--fail-unconverged", o.fail_unconverged,
               "A solve that stops without converging fails its job (the result is kept) "
               "instead of succeeding with converged false");
  app.add_flag("--admit-over-budget", o.admit_over_budget,
               "Queue and run cases estimated above --max-job-memory anyway (they run under the "
               "limit and fail if they exceed it)");
}

JobRunner service_job_runner(const WorkerOptions& options) {
  ProcessJobRunnerOptions runner;
  runner.memory_bytes = options.job_memory_bytes();
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  runner.threads = std::max(1, cores / std::max(1, options.workers));
  runner.max_job_seconds = options.max_job_seconds;
  runner.admission_memory_bytes = options.admission_memory_bytes();
  return process_job_runner(runner);
}

sigset_t block_stop_signals() {
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
  return stop_signals;
}

int wait_for_stop_signal(const sigset_t& stop_signals) {
  int signal_number = 0;
  sigwait(&stop_signals, &signal_number);
  std::thread([stop_signals] {
    int again = 0;
    sigwait(&stop_signals, &again);
    std::_Exit(128 + again);
  }).detach();
  return signal_number;
}

}  // namespace fosls::service
