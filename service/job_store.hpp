#pragma once
// The job store interface: everything the HTTP layer and the workers need from persistence.
// SQLite implements it today (sqlite_job_store.hpp); a PostgreSQL store with
// `FOR UPDATE SKIP LOCKED` could implement it to let several hosts share one queue.

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

/// A validated case to enqueue.
struct NewJob {
  std::string name;
  std::string case_json;  ///< canonical JSON text of the case
  std::string body_hash;  ///< SHA-256 (hex) of case_json
  std::optional<std::string> idempotency_key;
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

/// A job a worker has claimed, with the case to solve.
struct ClaimedJob {
  Job job;  ///< state running, attempts already counted
  std::string case_json;
};

/// Keyset pagination over jobs, newest first.
struct JobListQuery {
  std::optional<JobState> state;
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

/// What start-up recovery did with jobs a previous process left running.
struct RecoveryReport {
  std::vector<std::int64_t> requeued;
  std::vector<std::int64_t> failed;     ///< started max_attempts times already
  std::vector<std::int64_t> cancelled;  ///< a cancel had been requested before the crash
};

/// Persistent job queue and results. Implementations must be safe to call from many threads.
/// Completion calls carry the attempt number from the claim so that a stale worker can never
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

  /// VTU text of a succeeded job.
  virtual std::optional<std::string> vtu(std::int64_t id) = 0;

  virtual JobPage list(const JobListQuery& query) = 0;

  /// Cancels a queued job at once, or marks a running one so its worker stops it.
  virtual CancelOutcome cancel(std::int64_t id) = 0;

  /// Removes a finished job with its result.
  virtual DeleteOutcome remove(std::int64_t id) = 0;

  /// Moves the oldest queued job to running (attempts + 1) and returns it.
  virtual std::optional<ClaimedJob> claim_next() = 0;

  /// Records progress of a running attempt (no effect once it has finished).
  virtual void update_progress(std::int64_t id, int attempt, const JobProgress& progress) = 0;

  /// Stores the result and VTU of a running attempt and marks it succeeded, once.
  virtual bool complete_succeeded(std::int64_t id, int attempt, const std::string& result_json,
                                  const std::string& vtu) = 0;

  virtual bool complete_failed(std::int64_t id, int attempt, const std::string& error) = 0;

  virtual bool complete_cancelled(std::int64_t id, int attempt) = 0;

  /// Puts a running attempt back in the queue without counting it (graceful shutdown); a job
  /// whose cancel was requested becomes cancelled instead.
  virtual bool requeue(std::int64_t id, int attempt) = 0;

  /// Start-up recovery: jobs left running by a crashed process go back to the queue, or fail
  /// once they have been started max_attempts times.
  virtual RecoveryReport recover_interrupted(int max_attempts) = 0;

  /// Retention: deletes finished jobs that finished before the given time; returns how many.
  virtual int delete_finished_before(std::int64_t unix_ms) = 0;

  /// Number of jobs in each state (every state present, zero when none).
  virtual std::map<JobState, std::int64_t> count_by_state() = 0;

  /// Cheap round trip to the storage, for health checks; throws StoreError on failure.
  virtual void ping() = 0;
};

}  // namespace fosls::service
