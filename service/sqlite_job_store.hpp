#pragma once
// JobStore on an embedded SQLite database (zero set-up; one file plus its WAL).

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "job_store.hpp"
#include "sqlite_connection.hpp"

namespace fosls::service {

/// SQLite job store. Each calling thread gets its own connection (SQLite connections must not
/// be shared between threads), every read-then-write runs in BEGIN IMMEDIATE, and no call
/// holds a transaction longer than its own few statements, so a solve never blocks the queue.
class SqliteJobStore final : public JobStore {
 public:
  /// Opens (creating if needed) the database at `path` and its schema. Throws StoreError.
  explicit SqliteJobStore(std::string path, int busy_timeout_ms = 5000);

  SubmitOutcome submit(const NewJob& job, std::size_t max_queued) override;
  std::optional<Job> find(std::int64_t id) override;
  std::optional<std::string> result_json(std::int64_t id) override;
  std::optional<std::string> vtu(std::int64_t id) override;
  JobPage list(const JobListQuery& query) override;
  CancelOutcome cancel(std::int64_t id) override;
  DeleteOutcome remove(std::int64_t id) override;
  std::optional<ClaimedJob> claim_next() override;
  void update_progress(std::int64_t id, int attempt, const JobProgress& progress) override;
  bool complete_succeeded(std::int64_t id, int attempt, const std::string& result_json,
                          const std::string& vtu) override;
  bool complete_failed(std::int64_t id, int attempt, const std::string& error) override;
  bool complete_cancelled(std::int64_t id, int attempt) override;
  bool requeue(std::int64_t id, int attempt) override;
  RecoveryReport recover_interrupted(int max_attempts) override;
  int delete_finished_before(std::int64_t unix_ms) override;
  std::map<JobState, std::int64_t> count_by_state() override;
  void ping() override;

 private:
  /// This thread's connection, opened on first use.
  SqliteConnection& connection();
  void create_schema();
  std::optional<Job> find_on(SqliteConnection& c, std::int64_t id);

  std::string path_;
  int busy_timeout_ms_;
  std::mutex connections_mutex_;
  // Keyed by thread: a thread id is only reused after its thread ended, so a connection is
  // never used by two threads at once.
  std::map<std::thread::id, std::unique_ptr<SqliteConnection>> connections_;
};

}  // namespace fosls::service
