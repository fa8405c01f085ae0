#pragma once
// The job store interface: everything the HTTP layer and the workers need from persistence.
// Two implementations share one SQL text (sql_job_store.hpp): SQLite for one process
// (sqlite_job_store.hpp) and PostgreSQL for several API and worker processes on any hosts
// (postgres_job_store.hpp). docs/service.md, "Store", describes the contract.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "job.hpp"

namespace fosls::service {

/// A storage failure (I/O error, lock wait exceeded): the request or step may be retried.
class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The store's disk is full (SQLite's SQLITE_FULL, PostgreSQL's SQLSTATE 53100): nothing can be
/// written until space is freed, however often it is retried.
class StoreFullError : public StoreError {
 public:
  using StoreError::StoreError;
};

/// What GET /healthz says about the store beyond answering at all.
struct StoreHealth {
  bool disk_full = false;
  std::string detail;  ///< why, when disk_full: the store's message, or the free space left
};

/// A validated case to enqueue.
struct NewJob {
  std::string name;
  std::string case_json;  ///< canonical JSON text of the case
  std::string body_hash;  ///< SHA-256 (hex) of case_json
  std::optional<std::string> idempotency_key;
  /// Admission's estimate of the solve's time, kept so that the worker derives the job's time
  /// limit from it instead of reading the case again (none: not estimated).
  std::optional<double> time_estimate_seconds;
};

/// What a finished solve leaves to store.
struct SolveRecord {
  std::string result_json;
  std::string vtu;
  JobConvergence convergence;
  /// Empty: the job succeeded. Otherwise it fails for this reason although it has a result
  /// (a solve that did not converge under --fail-unconverged); the result is kept to look at.
  std::string error;
  /// The job was cancelled by its user after some of its load steps were solved: it ends
  /// cancelled, with those steps as its result (marked partial).
  bool cancelled = false;
};

/// How a job's VTU is stored: gzip-compressed (every result since SQLite's schema 2) or as
/// its text (older rows), and its stored size.
struct StoredVtu {
  bool gzip = false;
  std::int64_t bytes = 0;
};

/// What submit did.
struct SubmitOutcome {
  enum class Kind {
    kCreated,      ///< a new queued job
    kReplayed,     ///< the key was used before with the same body: the earlier job
    kKeyConflict,  ///< the key was used before with a different body: the earlier job
    kQueueFull,    ///< max_queued jobs are waiting; nothing stored
  };
  Kind kind = Kind::kCreated;
  std::optional<Job> job;  ///< set except for kQueueFull
};

/// Who may finish a running attempt: the attempt number of the claim and the worker that made
/// it. Every call that changes a running job carries it; a call from anyone else (a worker
/// whose lease expired and whose job was claimed again, or failed) changes nothing.
struct Lease {
  std::int64_t job_id = 0;
  int attempt = 0;
  std::string worker_id;
};

/// What a worker asks for when it claims: its identity and how long the lease lasts unless
/// renewed (renew_lease).
struct ClaimRequest {
  std::string worker_id;
  std::chrono::milliseconds lease_duration{30000};
};

/// A job a worker has claimed, with the case to solve.
struct ClaimedJob {
  Job job;  ///< state running, attempts already counted
  std::string case_json;
  Lease lease;
  std::optional<double> time_estimate_seconds;  ///< as submitted (NewJob)
};

/// What renewing a lease found.
enum class LeaseStatus {
  kHeld,             ///< still this worker's attempt; the expiry moved on
  kCancelRequested,  ///< renewed, and its user asked to cancel: stop the solve
  kLost,             ///< no longer this worker's attempt: stop, the outcome would be refused
};

/// Keyset pagination over jobs, newest first.
struct JobListQuery {
  std::optional<JobState> state;
  std::optional<bool> converged;  ///< only jobs whose solve did (true) or did not (false) converge
  int page_size = 20;
  std::optional<std::int64_t> before_id;  ///< only jobs with id < before_id
};

struct JobPage {
  std::vector<Job> jobs;
  std::optional<std::int64_t> next_before_id;  ///< set when more jobs follow
};

/// What cancel did.
struct CancelOutcome {
  enum class Kind {
    kCancelled,        ///< it was queued and is now cancelled
    kRequested,        ///< it is running; the worker must stop it
    kAlreadyFinished,  ///< nothing to cancel
    kNotFound,
  };
  Kind kind = Kind::kNotFound;
  std::optional<Job> job;  ///< the job after the call (unless kNotFound)
};

enum class DeleteOutcome { kDeleted, kNotFinished, kNotFound };

/// What recovery did with running jobs whose worker is gone (start-up recovery or expired
/// leases).
struct RecoveryReport {
  std::vector<std::int64_t> requeued;
  std::vector<std::int64_t> failed;     ///< started max_attempts times already
  std::vector<std::int64_t> cancelled;  ///< a cancel had been requested before the crash
};

/// Persistent job queue and results. Implementations must be safe to call from many threads.
/// Calls on a running job carry the Lease from its claim, so that a stale worker can never
/// overwrite a newer attempt (they return false and change nothing in that case).
class JobStore {
 public:
  virtual ~JobStore() = default;

  /// Enqueues a job unless the Idempotency-Key was used before or max_queued jobs wait,
  /// atomically (two requests with the same key never create two jobs).
  virtual SubmitOutcome submit(const NewJob& job, std::size_t max_queued) = 0;

  virtual std::optional<Job> find(std::int64_t id) = 0;

  /// Result JSON text of a succeeded job.
  virtual std::optional<std::string> result_json(std::int64_t id) = 0;

  /// The size in bytes of a job's result JSON; nothing when there is none.
  virtual std::optional<std::int64_t> result_json_size(std::int64_t id) = 0;

  /// Up to `length` bytes of the result JSON from `offset` (fewer at its end), sent in such
  /// parts as the VTU is (stored_vtu_bytes); nothing when the job or its result is gone.
  virtual std::optional<std::string> result_json_bytes(std::int64_t id, std::int64_t offset,
                                                       std::int64_t length) = 0;

  /// VTU text of a succeeded job.
  virtual std::optional<std::string> vtu(std::int64_t id) = 0;

  /// How the VTU of a job with a result is stored; nothing when there is none.
  virtual std::optional<StoredVtu> stored_vtu(std::int64_t id) = 0;

  /// Up to `length` of the VTU's stored bytes from `offset` (fewer at its end): a response
  /// streams the VTU in such parts instead of holding all of it per client. Nothing when the
  /// job or its result is gone (deleted meanwhile).
  virtual std::optional<std::string> stored_vtu_bytes(std::int64_t id, std::int64_t offset,
                                                      std::int64_t length) = 0;

  /// The case as submitted (canonical JSON text).
  virtual std::optional<std::string> case_json(std::int64_t id) = 0;

  virtual JobPage list(const JobListQuery& query) = 0;

  /// Cancels a queued job at once, or marks a running one so its worker stops it.
  virtual CancelOutcome cancel(std::int64_t id) = 0;

  /// Removes a finished job with its result.
  virtual DeleteOutcome remove(std::int64_t id) = 0;

  /// Moves the oldest queued job to running (attempts + 1) under a lease for the requesting
  /// worker and returns it. Concurrent claims, from any number of processes, never return the
  /// same attempt twice.
  virtual std::optional<ClaimedJob> claim_next(const ClaimRequest& request) = 0;

  /// Heartbeat of a running attempt: extends its lease to now + duration and reports whether a
  /// cancel was requested, or that the attempt is no longer this worker's.
  virtual LeaseStatus renew_lease(const Lease& lease, std::chrono::milliseconds duration) = 0;

  /// Records progress of a running attempt (no effect once it has finished).
  virtual void update_progress(const Lease& lease, const JobProgress& progress) = 0;

  /// Stores the result and VTU of a running attempt, once, and marks it succeeded (or failed
  /// when record.error is set).
  virtual bool complete_with_result(const Lease& lease, const SolveRecord& record) = 0;

  /// complete_with_result for a successful solve, its convergence read from the result.
  bool complete_succeeded(const Lease& lease, const std::string& result_json,
                          const std::string& vtu) {
    return complete_with_result(
        lease, SolveRecord{result_json, vtu, convergence_of_result(result_json), ""});
  }

  virtual bool complete_failed(const Lease& lease, const std::string& error) = 0;

  virtual bool complete_cancelled(const Lease& lease) = 0;

  /// Puts a running attempt back in the queue without counting it (graceful shutdown); a job
  /// whose cancel was requested becomes cancelled instead.
  virtual bool requeue(const Lease& lease) = 0;

  /// Lease expiry, safe to call from any process at any time: running jobs whose lease expired
  /// (their worker was killed or its host lost) go back to the queue with the attempt counted,
  /// are failed once they have been started max_attempts times, or are cancelled when a cancel
  /// was requested.
  virtual RecoveryReport requeue_expired_leases(int max_attempts) = 0;

  /// Start-up recovery of the sole owner of a store (fosls-serve on its SQLite file): every
  /// running job is treated as expired, whatever its lease says, since no other process can be
  /// working on it.
  virtual RecoveryReport recover_interrupted(int max_attempts) = 0;

  /// Retention: deletes finished jobs that finished before the given time; returns how many.
  virtual int delete_finished_before(std::int64_t unix_ms) = 0;

  /// Number of jobs in each state (every state present, zero when none).
  virtual std::map<JobState, std::int64_t> count_by_state() = 0;

  /// Number of jobs whose solve stopped without converging (succeeded or failed).
  virtual std::int64_t count_not_converged() = 0;

  /// Cheap round trip to the storage, for health checks; throws StoreError on failure.
  virtual void ping() = 0;

  /// Records (or renews) what a worker process gives each job (its --max-job-memory), under
  /// the process's worker id; workers renew it while they run.
  virtual void declare_worker_budget(const std::string& process_id, std::size_t bytes) = 0;
  /// The memory budget cases should be admitted against: the smallest of the workers that
  /// declared one within the last minute (any of them may claim any job), else the most recent
  /// declaration; nothing when no worker ever declared one.
  virtual std::optional<std::size_t> declared_worker_budget() = 0;

  /// ping(), and whether the store can write: a full disk does not stop reads, so it is told
  /// by the last disk-full error of any call (and, for a file, the free space left).
  virtual StoreHealth health() {
    ping();
    return {};
  }
};

}  // namespace fosls::service
