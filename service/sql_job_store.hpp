#pragma once
// The JobStore contract written once in SQL that SQLite and PostgreSQL both run
// (sql_connection.hpp). The two stores differ only in how they hand out connections, in their
// schema steps, and in the hooks below.

#include <functional>
#include <mutex>
#include <string>

#include "job_store.hpp"
#include "schema_migrations.hpp"
#include "sql_connection.hpp"

namespace fosls::service {

/// A JobStore over any SqlConnection. Each call borrows a connection for its few statements;
/// no transaction stays open between calls, so a solve never holds a lock. VTU text is stored
/// gzip-compressed.
class SqlJobStore : public JobStore {
 public:
  SubmitOutcome submit(const NewJob& job, std::size_t max_queued) override;
  std::optional<Job> find(std::int64_t id) override;
  std::optional<std::string> result_json(std::int64_t id) override;
  std::optional<std::string> vtu(std::int64_t id) override;
  std::optional<StoredVtu> stored_vtu(std::int64_t id) override;
  /// SQL's substr; the SQLite store reads only the part asked for (sqlite_job_store.hpp).
  std::optional<std::string> stored_vtu_bytes(std::int64_t id, std::int64_t offset,
                                              std::int64_t length) override;
  JobPage list(const JobListQuery& query) override;
  CancelOutcome cancel(std::int64_t id) override;
  DeleteOutcome remove(std::int64_t id) override;
  std::optional<ClaimedJob> claim_next(const ClaimRequest& request) override;
  LeaseStatus renew_lease(const Lease& lease, std::chrono::milliseconds duration) override;
  void update_progress(const Lease& lease, const JobProgress& progress) override;
  std::optional<std::string> case_json(std::int64_t id) override;
  bool complete_with_result(const Lease& lease, const SolveRecord& record) override;
  bool complete_failed(const Lease& lease, const std::string& error) override;
  bool complete_cancelled(const Lease& lease) override;
  bool requeue(const Lease& lease) override;
  RecoveryReport requeue_expired_leases(int max_attempts) override;
  RecoveryReport recover_interrupted(int max_attempts) override;
  int delete_finished_before(std::int64_t unix_ms) override;
  std::map<JobState, std::int64_t> count_by_state() override;
  std::int64_t count_not_converged() override;
  void ping() override;
  StoreHealth health() override;
  void declare_worker_budget(const std::string& process_id, std::size_t bytes) override;
  std::optional<std::size_t> declared_worker_budget() override;

 protected:
  /// `acquire` lends a connection to one call.
  explicit SqlJobStore(std::function<SqlConnectionHandle()> acquire);

  /// A store's schema: its own steps (`own`, which differ by dialect up to where the two
  /// schemas agree), then the steps both stores share, written once in sql_job_store.cpp in
  /// SQL both dialects run and numbered on from the last of `own`. A new column is one shared
  /// step.
  static std::vector<SchemaMigration> schema_steps(std::vector<SchemaMigration> own);

  SqlConnectionHandle connection() { return acquire_(); }

  /// Inside a submit transaction, before the queue is read: makes concurrent submits (from
  /// every process) take turns, so the queue bound and idempotency keys are exact.
  virtual void serialize_submits(SqlConnection& c) {}

  /// After jobs were deleted, outside any transaction: give the space back if the engine does
  /// not on its own.
  virtual void after_delete(SqlConnection& c) {}

  /// Gives a new connection's disk-full errors and commits to this store's health (call once
  /// per connection the store makes).
  void watch_disk(SqlConnection& c);

 private:
  std::optional<Job> find_on(SqlConnection& c, std::int64_t id);
  RecoveryReport recover(int max_attempts, bool only_expired);

  std::function<SqlConnectionHandle()> acquire_;
  /// The last disk-full error of any call and when it happened (steady clock, ms; 0 once a
  /// commit went through after it).
  mutable std::mutex disk_full_mutex_;
  std::string disk_full_message_;
  std::int64_t disk_full_at_ms_ = 0;
};

}  // namespace fosls::service
