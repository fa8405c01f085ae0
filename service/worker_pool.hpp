#pragma once
// Solver workers: each thread claims the oldest queued job under a lease, runs it with no
// database transaction open, and records the outcome; a heartbeat thread keeps the leases of
// running jobs alive and hears about cancels requested through any process. HTTP threads never
// solve.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "event_log.hpp"
#include "job_runner.hpp"
#include "job_store.hpp"
#include "metrics.hpp"

namespace fosls::service {

struct WorkerPoolOptions {
  /// Worker threads; 0 makes an API-only process (another process solves).
  int workers = 1;
  /// Identifies this process in leases; unique per process (make_worker_id()).
  std::string worker_id;
  /// A claimed job whose lease was not renewed for this long is taken back by the store.
  std::chrono::milliseconds lease_duration{30000};
  /// How often running jobs' leases are renewed and their cancel flags read from the store.
  std::chrono::milliseconds heartbeat_interval{1000};
  /// At most one progress write per job per interval.
  std::chrono::milliseconds progress_interval{500};
  /// How often idle workers look for jobs they were not told about.
  std::chrono::milliseconds idle_poll{1000};
  /// First pause before retrying a failed store write (doubles; five tries in all).
  std::chrono::milliseconds store_retry_delay{200};
  /// A solve that stops without converging fails its job (its result is kept) instead of
  /// succeeding with "converged": false (--fail-unconverged).
  bool fail_unconverged = false;
  /// The memory each job of this pool may use (--max-job-memory), declared in the store so that
  /// API-only processes admit cases against it; 0: not declared.
  std::size_t declared_job_memory = 0;
  /// How often the declaration is renewed (the store counts a worker live for a minute).
  std::chrono::milliseconds declare_interval{10000};
};

/// hostname:pid:random, unique to one process even where pids repeat (containers).
std::string make_worker_id();

/// A fixed set of worker threads over a JobStore.
class WorkerPool {
 public:
  /// `store`, `log` and `metrics` must outlive the pool.
  WorkerPool(JobStore& store, JobRunner runner, EventLog& log, Metrics& metrics,
             WorkerPoolOptions options);
  /// Stops like begin_shutdown() + join().
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void start();

  /// Wakes idle workers (a job was just queued).
  void notify_job_available();

  /// Stops a running job of this process on behalf of its user (the store already has
  /// cancel_requested set); safe even if the job has not reached its worker yet.
  void request_cancel(std::int64_t job_id);

  /// Stops claiming and cancels running solves; those jobs go back to the queue without
  /// counting the attempt. Returns at once; join() waits.
  void begin_shutdown();

  /// Waits for every worker to finish its current job.
  void join();

  int size() const { return options_.workers; }
  int busy() const { return busy_.load(); }

 private:
  struct ActiveJob {
    Lease lease;
    std::shared_ptr<std::atomic<bool>> cancel;
    bool user_cancel = false;
    bool lease_lost = false;  ///< the store gave the attempt to someone else
  };

  /// What the pool knew about a run when it ended.
  struct RunEnd {
    bool user_cancel = false;
    bool lease_lost = false;
    bool stopping = false;
  };

  void run_worker(int index);
  /// Registers, solves, unregisters and records one claimed job (the steps below).
  void run_job(const ClaimedJob& claimed);
  /// Makes the job cancellable through this pool; its cancel flag is set at once when a cancel
  /// came before the worker or the pool is stopping.
  std::shared_ptr<std::atomic<bool>> register_job(const ClaimedJob& claimed);
  /// The runner's outcome; any exception becomes a failed outcome.
  JobRunOutcome solve(const ClaimedJob& claimed, const JobRunContext& context);
  RunEnd unregister_job(std::int64_t job_id);
  /// Writes the outcome to the store (with retries) and counts it; returns the fields of the
  /// job_transition log line.
  nlohmann::json record_outcome(const Lease& lease, JobRunOutcome& outcome, const RunEnd& end,
                                double seconds);
  /// The succeeded (or, under fail_unconverged, failed) result; a result the store refuses
  /// turns `outcome` into a failure to be stored instead.
  bool store_result(const Lease& lease, JobRunOutcome& outcome, double seconds,
                    nlohmann::json& fields);
  /// Renews the lease of every running job until shutdown; stops a job whose cancel was
  /// requested (through any process) or whose lease was lost.
  void run_heartbeat();
  void heartbeat_once();
  /// Declares (renews) declared_job_memory in the store; a store error is logged, not fatal.
  void declare_budget();
  /// Why a job whose solve did not converge fails under fail_unconverged.
  static std::string unconverged_error(const JobConvergence& convergence);
  /// Calls `write` until it returns without throwing or attempts run out (the store may be
  /// busy for a while); returns what `write` returned, false after the last failure, whose
  /// message goes to `error`.
  bool with_retries(const char* what, std::int64_t job_id, const std::function<bool()>& write,
                    std::string& error);

  JobStore& store_;
  JobRunner runner_;
  EventLog& log_;
  Metrics& metrics_;
  WorkerPoolOptions options_;

  std::mutex mutex_;
  std::condition_variable wake_;
  std::uint64_t generation_ = 0;  ///< bumped by notify_job_available
  bool stopping_ = false;
  bool heartbeat_stopping_ = false;  ///< set once every worker has finished
  std::map<std::int64_t, ActiveJob> active_;
  std::set<std::int64_t> early_cancels_;  ///< cancels that arrived before the worker did
  std::atomic<int> busy_{0};
  std::vector<std::thread> threads_;
  std::thread heartbeat_;
};

}  // namespace fosls::service
