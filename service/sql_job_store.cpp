#include "sql_job_store.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "gzip.hpp"

namespace fosls::service {

namespace {

// The columns a Job is read from (read_job), in every statement that returns jobs.
constexpr const char* kJobColumns =
    "id, name, state, created_at, started_at, finished_at, attempts, progress_iteration, "
    "progress_kkt_residual, progress_energy, progress_step, progress_steps, error, "
    "cancel_requested, converged, stop_reason";

// What a new attempt (a claim, a requeue after a crash) clears: the last attempt's progress.
constexpr const char* kNoProgress =
    "progress_iteration = NULL, progress_kkt_residual = NULL, progress_energy = NULL, "
    "progress_step = NULL, progress_steps = NULL";

std::string select_job_sql(const std::string& where) {
  return std::string("SELECT ") + kJobColumns + " FROM jobs " + where;
}

// The condition every write on a running attempt carries: only the holder of the lease from
// its claim may change it (parameters ?1 id, ?2 attempt, ?3 worker).
constexpr const char* kLeaseHolder =
    "id = ?1 AND state = 'running' AND attempts = ?2 AND lease_owner = ?3";

std::vector<SqlValue> lease_params(const Lease& lease) {
  return {lease.job_id, static_cast<std::int64_t>(lease.attempt), lease.worker_id};
}

Job read_job(const SqlRow& row) {
  Job job;
  job.id = row.int64("id");
  job.name = row.text("name");
  // The CHECK constraint keeps the column to the five known words.
  job.state = parse_job_state(row.text("state")).value_or(JobState::kFailed);
  job.created_at_ms = row.int64("created_at");
  job.started_at_ms = row.optional_int64("started_at");
  job.finished_at_ms = row.optional_int64("finished_at");
  job.attempts = static_cast<int>(row.int64("attempts"));
  if (!row.is_null("progress_iteration")) {
    JobProgress p;
    p.iteration = static_cast<int>(row.int64("progress_iteration"));
    // NaN and infinities are stored as NULL, which real() reads as NaN.
    p.kkt_residual = row.real("progress_kkt_residual");
    p.energy = row.real("progress_energy");
    // NULL: written before the columns existed (step 0 of a number not known).
    p.step = static_cast<int>(row.optional_int64("progress_step").value_or(0));
    p.steps = static_cast<int>(row.optional_int64("progress_steps").value_or(0));
    job.progress = p;
  }
  job.error = row.text("error");
  job.cancel_requested = row.int64("cancel_requested") != 0;
  if (!row.is_null("converged")) job.convergence.converged = row.int64("converged") != 0;
  job.convergence.stop_reason = row.text("stop_reason");
  return job;
}

constexpr const char* kFinishedStates = "('succeeded', 'failed', 'cancelled')";

// Steps after SQLite's version 3 and PostgreSQL's version 2, where both schemas are the same;
// each text must run in both dialects (docs/service.md lists the versions).
const std::vector<SchemaMigration> kSharedSteps = {
    // What each worker process may give a job (--max-job-memory), so that API-only processes
    // admit cases against the workers' budget, not their own (docs/service.md, "Command line").
    {0, "the workers' memory budgets", R"sql(
CREATE TABLE worker_budgets (
  process_id TEXT PRIMARY KEY,
  max_job_memory BIGINT NOT NULL,
  seen_at BIGINT NOT NULL
);
)sql"},
    // Which solve of a multi-solve job (load steps, sweep, adaptivity) the progress is of.
    // Rows from before stay NULL: read as step 0 of a number not known.
    {0, "progress per solve of a multi-solve job", R"sql(
ALTER TABLE jobs ADD COLUMN progress_step INTEGER;
ALTER TABLE jobs ADD COLUMN progress_steps INTEGER;
)sql"},
    // Admission's time estimate, from which workers derive the job's time limit without
    // reading the case again (issue 50). Rows from before stay NULL: the cap applies.
    {0, "the time estimate of each job", R"sql(
ALTER TABLE jobs ADD COLUMN time_estimate_s DOUBLE PRECISION;
)sql"},
};

/// Workers renew their declaration with their leases; one seen this recently still runs.
constexpr std::int64_t kLiveWorkerMs = 60000;
/// Declarations older than this are deleted (a process that stopped long ago).
constexpr std::int64_t kForgetWorkerMs = 7 * 24 * 3600 * 1000LL;

}  // namespace

std::vector<SchemaMigration> SqlJobStore::schema_steps(std::vector<SchemaMigration> own) {
  int version = own.empty() ? 0 : own.back().version;
  for (SchemaMigration step : kSharedSteps) {
    step.version = ++version;
    own.push_back(std::move(step));
  }
  return own;
}

SqlJobStore::SqlJobStore(std::function<SqlConnectionHandle()> acquire)
    : acquire_(std::move(acquire)) {}

std::optional<Job> SqlJobStore::find_on(SqlConnection& c, std::int64_t id) {
  const SqlRows rows = c.query(select_job_sql("WHERE id = ?1"), {id});
  if (rows.empty()) return std::nullopt;
  return read_job(rows[0]);
}

SubmitOutcome SqlJobStore::submit(const NewJob& job, std::size_t max_queued) {
  auto c = connection();
  SqlTransaction tx(*c);
  serialize_submits(*c);
  SubmitOutcome out;
  if (job.idempotency_key) {
    const SqlRows existing = c->query("SELECT id, body_hash FROM jobs WHERE idempotency_key = ?1",
                                      {*job.idempotency_key});
    if (!existing.empty()) {
      out.kind = existing[0].text("body_hash") == job.body_hash ? SubmitOutcome::Kind::kReplayed
                                                                : SubmitOutcome::Kind::kKeyConflict;
      out.job = find_on(*c, existing[0].int64("id"));
      tx.commit();
      return out;
    }
  }
  const std::int64_t queued =
      c->query("SELECT count(*) AS n FROM jobs WHERE state = 'queued'")[0].int64("n");
  if (static_cast<std::size_t>(queued) >= max_queued) {
    out.kind = SubmitOutcome::Kind::kQueueFull;
    return out;  // rolls back: nothing was written
  }
  const SqlRows inserted = c->query(
      "INSERT INTO jobs (name, state, case_json, idempotency_key, body_hash, time_estimate_s, "
      "created_at) VALUES (?1, 'queued', ?2, ?3, ?4, ?5, {now_ms}) RETURNING " +
          std::string(kJobColumns),
      {job.name, job.case_json, sql_optional(job.idempotency_key), job.body_hash,
       job.time_estimate_seconds ? SqlValue(*job.time_estimate_seconds) : SqlValue()});
  out.kind = SubmitOutcome::Kind::kCreated;
  out.job = read_job(inserted.at(0));
  tx.commit();
  return out;
}

std::optional<Job> SqlJobStore::find(std::int64_t id) { return find_on(*connection(), id); }

std::optional<std::string> SqlJobStore::result_json(std::int64_t id) {
  const SqlRows rows =
      connection()->query("SELECT result_json FROM job_results WHERE job_id = ?1", {id});
  if (rows.empty()) return std::nullopt;
  return rows[0].text("result_json");
}

std::optional<std::string> SqlJobStore::case_json(std::int64_t id) {
  const SqlRows rows = connection()->query("SELECT case_json FROM jobs WHERE id = ?1", {id});
  if (rows.empty()) return std::nullopt;
  return rows[0].text("case_json");
}

std::optional<std::string> SqlJobStore::vtu(std::int64_t id) {
  const SqlRows rows =
      connection()->query("SELECT vtu, vtu_encoding FROM job_results WHERE job_id = ?1", {id});
  if (rows.empty()) return std::nullopt;
  // Rows written before compression was introduced are kept as they were ('identity').
  if (rows[0].text("vtu_encoding") == "gzip") return gzip_decompress(rows[0].text("vtu"));
  return rows[0].text("vtu");
}

std::optional<StoredVtu> SqlJobStore::stored_vtu(std::int64_t id) {
  // length() of a blob reads its size, not its bytes (SQLite and PostgreSQL alike).
  const SqlRows rows = connection()->query(
      "SELECT vtu_encoding, length(vtu) AS bytes FROM job_results WHERE job_id = ?1", {id});
  if (rows.empty()) return std::nullopt;
  return StoredVtu{rows[0].text("vtu_encoding") == "gzip", rows[0].int64("bytes")};
}

std::optional<std::string> SqlJobStore::stored_vtu_bytes(std::int64_t id, std::int64_t offset,
                                                         std::int64_t length) {
  // PostgreSQL reads only the TOAST chunks of the part (the column is stored uncompressed).
  const SqlRows rows =
      connection()->query("SELECT substr(vtu, ?2, ?3) AS part FROM job_results WHERE job_id = ?1",
                          {id, offset + 1, length});
  if (rows.empty()) return std::nullopt;
  return rows[0].text("part");
}

JobPage SqlJobStore::list(const JobListQuery& query) {
  // One statement text per filter combination, so each one uses the right index; parameters
  // are numbered in the order they appear (PostgreSQL needs every number used).
  std::string where;
  std::vector<SqlValue> params;
  if (query.state) {
    params.emplace_back(std::string(to_string(*query.state)));
    where += "state = ?" + std::to_string(params.size());
  }
  if (query.converged) {
    params.emplace_back(static_cast<std::int64_t>(*query.converged));
    where +=
        std::string(where.empty() ? "" : " AND ") + "converged = ?" + std::to_string(params.size());
  }
  if (query.before_id) {
    params.emplace_back(*query.before_id);
    where += std::string(where.empty() ? "" : " AND ") + "id < ?" + std::to_string(params.size());
  }
  const int page_size = std::max(1, query.page_size);
  params.emplace_back(static_cast<std::int64_t>(page_size) + 1);  // one more: does a page follow?
  const std::string sql = select_job_sql(where.empty() ? "" : "WHERE " + where) +
                          " ORDER BY id DESC LIMIT ?" + std::to_string(params.size());
  const SqlRows rows = connection()->query(sql, params);
  JobPage page;
  for (const SqlRow& row : rows) {
    if (static_cast<int>(page.jobs.size()) == page_size) {
      page.next_before_id = page.jobs.back().id;
      break;
    }
    page.jobs.push_back(read_job(row));
  }
  return page;
}

CancelOutcome SqlJobStore::cancel(std::int64_t id) {
  auto c = connection();
  SqlTransaction tx(*c);
  CancelOutcome out;
  // Each UPDATE re-checks the state it expects, so a claim or a completion by another process
  // between them cannot be overwritten.
  if (!c->query("UPDATE jobs SET state = 'cancelled', cancel_requested = 1, finished_at = "
                "{now_ms} WHERE id = ?1 AND state = 'queued' RETURNING id",
                {id})
           .empty()) {
    out.kind = CancelOutcome::Kind::kCancelled;
  } else if (!c->query("UPDATE jobs SET cancel_requested = 1 WHERE id = ?1 AND state = "
                       "'running' RETURNING id",
                       {id})
                  .empty()) {
    out.kind = CancelOutcome::Kind::kRequested;
  }
  out.job = find_on(*c, id);
  if (!out.job) {
    out.kind = CancelOutcome::Kind::kNotFound;
  } else if (out.kind == CancelOutcome::Kind::kNotFound) {
    out.kind = CancelOutcome::Kind::kAlreadyFinished;
  }
  tx.commit();
  return out;
}

DeleteOutcome SqlJobStore::remove(std::int64_t id) {
  auto c = connection();
  {
    SqlTransaction tx(*c);
    // job_results rows go with it (ON DELETE CASCADE).
    const bool deleted = !c->query("DELETE FROM jobs WHERE id = ?1 AND state IN " +
                                       std::string(kFinishedStates) + " RETURNING id",
                                   {id})
                              .empty();
    if (!deleted) {
      return c->query("SELECT 1 FROM jobs WHERE id = ?1", {id}).empty()
                 ? DeleteOutcome::kNotFound
                 : DeleteOutcome::kNotFinished;
    }
    tx.commit();
  }
  after_delete(*c);
  return DeleteOutcome::kDeleted;
}

std::optional<ClaimedJob> SqlJobStore::claim_next(const ClaimRequest& request) {
  auto c = connection();
  // Unlocked peek first: idle workers poll, and must not take the write lock to find nothing.
  if (c->query("SELECT 1 FROM jobs WHERE state = 'queued' LIMIT 1").empty()) return std::nullopt;
  SqlTransaction tx(*c);
  // PostgreSQL: rows another claimer has locked are skipped, not waited for, so concurrent
  // claims from many workers take different jobs. SQLite: the write lock serialises claims.
  const SqlRows rows = c->query(
      "UPDATE jobs SET state = 'running', attempts = attempts + 1, started_at = {now_ms}, "
      "lease_owner = ?1, lease_expires_at = {now_ms} + ?2, " +
          std::string(kNoProgress) +
          " WHERE state = 'queued' AND id = (SELECT id FROM jobs WHERE state = 'queued' "
          "ORDER BY id LIMIT 1 {skip_locked}) RETURNING " +
          kJobColumns + ", case_json, time_estimate_s",
      {request.worker_id, static_cast<std::int64_t>(request.lease_duration.count())});
  if (rows.empty()) return std::nullopt;  // another worker was faster
  tx.commit();
  ClaimedJob claimed;
  claimed.job = read_job(rows[0]);
  claimed.case_json = rows[0].text("case_json");
  claimed.lease = Lease{claimed.job.id, claimed.job.attempts, request.worker_id};
  if (!rows[0].is_null("time_estimate_s"))
    claimed.time_estimate_seconds = rows[0].real("time_estimate_s");
  return claimed;
}

LeaseStatus SqlJobStore::renew_lease(const Lease& lease, std::chrono::milliseconds duration) {
  std::vector<SqlValue> params = lease_params(lease);
  params.emplace_back(static_cast<std::int64_t>(duration.count()));
  const SqlRows rows =
      connection()->query("UPDATE jobs SET lease_expires_at = {now_ms} + ?4 WHERE " +
                              std::string(kLeaseHolder) + " RETURNING cancel_requested",
                          params);
  if (rows.empty()) return LeaseStatus::kLost;
  return rows[0].int64("cancel_requested") != 0 ? LeaseStatus::kCancelRequested
                                                : LeaseStatus::kHeld;
}

void SqlJobStore::update_progress(const Lease& lease, const JobProgress& progress) {
  // A single autocommit statement: no transaction stays open while the solver runs.
  std::vector<SqlValue> params = lease_params(lease);
  params.insert(params.end(),
                {static_cast<std::int64_t>(progress.iteration), progress.kkt_residual,
                 progress.energy, static_cast<std::int64_t>(progress.step),
                 progress.steps > 0 ? SqlValue(std::int64_t{progress.steps}) : SqlValue{}});
  connection()->query(
      "UPDATE jobs SET progress_iteration = ?4, progress_kkt_residual = ?5, "
      "progress_energy = ?6, progress_step = ?7, progress_steps = ?8 WHERE " +
          std::string(kLeaseHolder),
      params);
}

bool SqlJobStore::complete_with_result(const Lease& lease, const SolveRecord& record) {
  // Compressed before the transaction: the write lock is never held for the CPU work.
  SqlBlob compressed{gzip_compress(record.vtu)};
  std::vector<SqlValue> params = lease_params(lease);
  params.emplace_back(std::string(record.cancelled       ? "cancelled"
                                  : record.error.empty() ? "succeeded"
                                                         : "failed"));
  params.emplace_back(record.error.empty() ? SqlValue{} : SqlValue(record.error));
  params.emplace_back(record.convergence.converged
                          ? SqlValue(static_cast<std::int64_t>(*record.convergence.converged))
                          : SqlValue{});
  params.emplace_back(record.convergence.stop_reason.empty()
                          ? SqlValue{}
                          : SqlValue(record.convergence.stop_reason));
  auto c = connection();
  SqlTransaction tx(*c);
  if (c->query("UPDATE jobs SET state = ?4, finished_at = {now_ms}, error = ?5, converged = ?6, "
               "stop_reason = ?7, lease_owner = NULL, lease_expires_at = NULL WHERE " +
                   std::string(kLeaseHolder) + " RETURNING id",
               params)
          .empty()) {
    return false;  // not this worker's attempt any more
  }
  // job_id is the primary key: a second result for a job is impossible, not just avoided.
  c->query(
      "INSERT INTO job_results (job_id, result_json, vtu, vtu_encoding, written_at) "
      "VALUES (?1, ?2, ?3, 'gzip', {now_ms})",
      {lease.job_id, record.result_json, std::move(compressed)});
  tx.commit();
  return true;
}

bool SqlJobStore::complete_failed(const Lease& lease, const std::string& error) {
  std::vector<SqlValue> params = lease_params(lease);
  params.emplace_back(error);
  return !connection()
              ->query(
                  "UPDATE jobs SET state = 'failed', finished_at = {now_ms}, error = ?4, "
                  "lease_owner = NULL, lease_expires_at = NULL WHERE " +
                      std::string(kLeaseHolder) + " RETURNING id",
                  params)
              .empty();
}

bool SqlJobStore::complete_cancelled(const Lease& lease) {
  return !connection()
              ->query(
                  "UPDATE jobs SET state = 'cancelled', finished_at = {now_ms}, "
                  "lease_owner = NULL, lease_expires_at = NULL WHERE " +
                      std::string(kLeaseHolder) + " RETURNING id",
                  lease_params(lease))
              .empty();
}

bool SqlJobStore::requeue(const Lease& lease) {
  return !connection()
              ->query(
                  "UPDATE jobs SET "
                  "state = CASE WHEN cancel_requested <> 0 THEN 'cancelled' ELSE 'queued' END, "
                  "attempts = CASE WHEN cancel_requested <> 0 THEN attempts "
                  "ELSE attempts - 1 END, "
                  "finished_at = CASE WHEN cancel_requested <> 0 THEN {now_ms} END, "
                  "started_at = CASE WHEN cancel_requested <> 0 THEN started_at END, "
                  "lease_owner = NULL, lease_expires_at = NULL WHERE " +
                      std::string(kLeaseHolder) + " RETURNING id",
                  lease_params(lease))
              .empty();
}

RecoveryReport SqlJobStore::requeue_expired_leases(int max_attempts) {
  return recover(max_attempts, true);
}

RecoveryReport SqlJobStore::recover_interrupted(int max_attempts) {
  return recover(max_attempts, false);
}

RecoveryReport SqlJobStore::recover(int max_attempts, bool only_expired) {
  // Three disjoint outcomes for abandoned jobs: cancelled if its user asked; failed once it has
  // been started max_attempts times (a case that kills its worker must not loop forever); else
  // queued again with the attempt counted. A job without a lease (left by an older program)
  // counts as expired.
  const std::string abandoned =
      std::string(" WHERE state = 'running'") +
      (only_expired ? " AND (lease_expires_at IS NULL OR lease_expires_at < {now_ms})" : "");
  const std::string finished = ", lease_owner = NULL, lease_expires_at = NULL";
  const std::vector<SqlValue> limit = {static_cast<std::int64_t>(max_attempts)};
  auto ids = [](const SqlRows& rows) {
    std::vector<std::int64_t> out;
    for (const SqlRow& row : rows) out.push_back(row.int64("id"));
    std::sort(out.begin(), out.end());
    return out;
  };
  auto c = connection();
  SqlTransaction tx(*c);
  RecoveryReport report;
  report.cancelled =
      ids(c->query("UPDATE jobs SET state = 'cancelled', finished_at = {now_ms}" + finished +
                   abandoned + " AND cancel_requested <> 0 RETURNING id"));
  report.failed = ids(c->query(
      "UPDATE jobs SET state = 'failed', finished_at = {now_ms}, error = 'its worker stopped "
      "(crash, kill or lost host) while solving this job ' || attempts || ' times (limit "
      "--max-attempts); it is not retried again'" +
          finished + abandoned + " AND cancel_requested = 0 AND attempts >= ?1 RETURNING id",
      limit));
  report.requeued = ids(c->query("UPDATE jobs SET state = 'queued', started_at = NULL, " +
                                     std::string(kNoProgress) + finished + abandoned +
                                     " AND cancel_requested = 0 AND attempts < ?1 RETURNING id",
                                 limit));
  tx.commit();
  return report;
}

int SqlJobStore::delete_finished_before(std::int64_t unix_ms) {
  auto c = connection();
  int total = 0;
  // Small batches so that no lock (and the VTU freed) is held for long.
  for (;;) {
    const auto n = c->query(
                        "DELETE FROM jobs WHERE id IN (SELECT id FROM jobs WHERE finished_at "
                        "IS NOT NULL AND finished_at < ?1 AND state IN " +
                            std::string(kFinishedStates) + " LIMIT 100) RETURNING id",
                        {unix_ms})
                       .size();
    total += static_cast<int>(n);
    if (n < 100) break;
  }
  if (total > 0) after_delete(*c);
  return total;
}

std::map<JobState, std::int64_t> SqlJobStore::count_by_state() {
  std::map<JobState, std::int64_t> counts;
  for (JobState s : kAllJobStates) counts[s] = 0;
  for (const SqlRow& row :
       connection()->query("SELECT state, count(*) AS n FROM jobs GROUP BY state")) {
    if (auto s = parse_job_state(row.text("state"))) counts[*s] = row.int64("n");
  }
  return counts;
}

std::int64_t SqlJobStore::count_not_converged() {
  return connection()->query("SELECT count(*) AS n FROM jobs WHERE converged = 0")[0].int64("n");
}

void SqlJobStore::ping() { connection()->query("SELECT 1"); }

void SqlJobStore::declare_worker_budget(const std::string& process_id, std::size_t bytes) {
  auto c = connection();
  c->query(
      "INSERT INTO worker_budgets (process_id, max_job_memory, seen_at) "
      "VALUES (?1, ?2, {now_ms}) ON CONFLICT (process_id) DO UPDATE SET "
      "max_job_memory = excluded.max_job_memory, seen_at = excluded.seen_at",
      {process_id, static_cast<std::int64_t>(bytes)});
  c->query("DELETE FROM worker_budgets WHERE seen_at < {now_ms} - ?1", {kForgetWorkerMs});
}

std::optional<std::size_t> SqlJobStore::declared_worker_budget() {
  auto c = connection();
  // Any live worker may claim any job: admit what the smallest of them can run.
  const SqlRows live = c->query(
      "SELECT min(max_job_memory) AS bytes FROM worker_budgets WHERE seen_at >= {now_ms} - ?1",
      {kLiveWorkerMs});
  if (!live.empty() && !live[0].is_null("bytes"))
    return static_cast<std::size_t>(live[0].int64("bytes"));
  // None running now: the workers that ran last will most likely run the job.
  const SqlRows last =
      c->query("SELECT max_job_memory AS bytes FROM worker_budgets ORDER BY seen_at DESC LIMIT 1");
  if (last.empty()) return std::nullopt;
  return static_cast<std::size_t>(last[0].int64("bytes"));
}

namespace {
/// A disk-full error makes the store unhealthy until a commit goes through, or this long: every
/// worker and request that meets the full disk renews it.
constexpr std::int64_t kDiskFullMemoryMs = 30000;

std::int64_t steady_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
}  // namespace

void SqlJobStore::watch_disk(SqlConnection& c) {
  c.observe_disk([this](bool full, const std::string& message) {
    std::lock_guard lock(disk_full_mutex_);
    if (!full) {
      disk_full_at_ms_ = 0;  // the disk took a commit: it has room again
      return;
    }
    disk_full_message_ = message;
    disk_full_at_ms_ = steady_ms();
  });
}

StoreHealth SqlJobStore::health() {
  ping();
  StoreHealth health;
  std::lock_guard lock(disk_full_mutex_);
  if (disk_full_at_ms_ != 0 && steady_ms() - disk_full_at_ms_ < kDiskFullMemoryMs) {
    health.disk_full = true;
    health.detail = disk_full_message_;
  }
  return health;
}

}  // namespace fosls::service
