#include "sqlite_job_store.hpp"

#include <cmath>
#include <string>

namespace fosls::service {

namespace {

constexpr int kSchemaVersion = 1;

// Results live in their own table so that listing jobs never reads result or VTU text, and
// job_id as primary key makes "a result is written once" a constraint, not a hope.
constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS jobs (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  name TEXT NOT NULL,
  state TEXT NOT NULL
    CHECK (state IN ('queued', 'running', 'succeeded', 'failed', 'cancelled')),
  case_json TEXT NOT NULL,
  idempotency_key TEXT UNIQUE,
  body_hash TEXT NOT NULL,
  error TEXT,
  progress_iteration INTEGER,
  progress_kkt_residual REAL,
  progress_energy REAL,
  attempts INTEGER NOT NULL DEFAULT 0,
  cancel_requested INTEGER NOT NULL DEFAULT 0,
  created_at INTEGER NOT NULL,
  started_at INTEGER,
  finished_at INTEGER
);
CREATE INDEX IF NOT EXISTS jobs_by_state ON jobs(state, id);
CREATE INDEX IF NOT EXISTS jobs_by_finished_at ON jobs(finished_at)
  WHERE finished_at IS NOT NULL;
CREATE TABLE IF NOT EXISTS job_results (
  job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,
  result_json TEXT NOT NULL,
  vtu TEXT NOT NULL,
  written_at INTEGER NOT NULL
);
)sql";

constexpr const char* kJobColumns =
    "id, name, state, created_at, started_at, finished_at, attempts, progress_iteration, "
    "progress_kkt_residual, progress_energy, error, cancel_requested";

std::string select_job_sql(const std::string& where) {
  return std::string("SELECT ") + kJobColumns + " FROM jobs " + where;
}

Job read_job(const SqliteQuery& q) {
  Job job;
  job.id = q.int64(0);
  job.name = q.text(1);
  const std::string state = q.text(2);
  // The CHECK constraint keeps the column to the five known words.
  job.state = parse_job_state(state).value_or(JobState::kFailed);
  job.created_at_ms = q.int64(3);
  job.started_at_ms = q.optional_int64(4);
  job.finished_at_ms = q.optional_int64(5);
  job.attempts = static_cast<int>(q.int64(6));
  if (!q.is_null(7)) {
    JobProgress p;
    p.iteration = static_cast<int>(q.int64(7));
    // SQLite stores NaN as NULL.
    p.kkt_residual = q.is_null(8) ? std::nan("") : q.real(8);
    p.energy = q.is_null(9) ? std::nan("") : q.real(9);
    job.progress = p;
  }
  job.error = q.text(10);
  job.cancel_requested = q.int64(11) != 0;
  return job;
}

std::optional<JobState> state_of(SqliteConnection& c, std::int64_t id) {
  SqliteQuery q(c, "SELECT state FROM jobs WHERE id = ?");
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  return parse_job_state(q.text(0));
}

}  // namespace

SqliteJobStore::SqliteJobStore(std::string path, int busy_timeout_ms)
    : path_(std::move(path)), busy_timeout_ms_(busy_timeout_ms) {
  create_schema();
}

SqliteConnection& SqliteJobStore::connection() {
  std::lock_guard lock(connections_mutex_);
  auto& slot = connections_[std::this_thread::get_id()];
  if (!slot) slot = std::make_unique<SqliteConnection>(path_, busy_timeout_ms_);
  return *slot;
}

void SqliteJobStore::create_schema() {
  SqliteConnection& c = connection();
  ImmediateTransaction tx(c);
  std::int64_t version = 0;
  {
    SqliteQuery q(c, "PRAGMA user_version");
    if (q.step()) version = q.int64(0);
  }
  if (version > kSchemaVersion) {
    throw StoreError("database '" + path_ + "' has schema version " + std::to_string(version) +
                     ", newer than this program understands (" + std::to_string(kSchemaVersion) +
                     ")");
  }
  c.exec(kSchema);
  c.exec(("PRAGMA user_version = " + std::to_string(kSchemaVersion)).c_str());
  tx.commit();
}

std::optional<Job> SqliteJobStore::find_on(SqliteConnection& c, std::int64_t id) {
  SqliteQuery q(c, select_job_sql("WHERE id = ?"));
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  return read_job(q);
}

SubmitOutcome SqliteJobStore::submit(const NewJob& job, std::size_t max_queued) {
  SqliteConnection& c = connection();
  ImmediateTransaction tx(c);
  SubmitOutcome out;
  if (job.idempotency_key) {
    std::optional<std::int64_t> existing;
    std::string existing_hash;
    {
      SqliteQuery q(c, "SELECT id, body_hash FROM jobs WHERE idempotency_key = ?");
      q.bind(1, *job.idempotency_key);
      if (q.step()) {
        existing = q.int64(0);
        existing_hash = q.text(1);
      }
    }
    if (existing) {
      out.kind = existing_hash == job.body_hash ? SubmitOutcome::Kind::kReplayed
                                                : SubmitOutcome::Kind::kKeyConflict;
      out.job = find_on(c, *existing);
      tx.commit();
      return out;
    }
  }
  {
    SqliteQuery q(c, "SELECT count(*) FROM jobs WHERE state = 'queued'");
    q.step();
    if (static_cast<std::size_t>(q.int64(0)) >= max_queued) {
      out.kind = SubmitOutcome::Kind::kQueueFull;
      return out;  // rolls back: nothing was written
    }
  }
  {
    SqliteQuery q(c,
                  "INSERT INTO jobs (name, state, case_json, idempotency_key, body_hash, "
                  "created_at) VALUES (?, 'queued', ?, ?, ?, ?)");
    q.bind(1, std::string_view(job.name))
        .bind(2, std::string_view(job.case_json))
        .bind(3, job.idempotency_key)
        .bind(4, std::string_view(job.body_hash))
        .bind(5, now_unix_ms());
    q.run();
  }
  out.kind = SubmitOutcome::Kind::kCreated;
  out.job = find_on(c, c.last_insert_rowid());
  tx.commit();
  return out;
}

std::optional<Job> SqliteJobStore::find(std::int64_t id) { return find_on(connection(), id); }

std::optional<std::string> SqliteJobStore::result_json(std::int64_t id) {
  SqliteQuery q(connection(), "SELECT result_json FROM job_results WHERE job_id = ?");
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  return q.text(0);
}

std::optional<std::string> SqliteJobStore::vtu(std::int64_t id) {
  SqliteQuery q(connection(), "SELECT vtu FROM job_results WHERE job_id = ?");
  q.bind(1, id);
  if (!q.step()) return std::nullopt;
  return q.text(0);
}

JobPage SqliteJobStore::list(const JobListQuery& query) {
  // Separate statement texts per filter combination so each one uses the right index.
  std::string where;
  if (query.state) where += "state = ?1";
  if (query.before_id) where += std::string(where.empty() ? "" : " AND ") + "id < ?2";
  std::string sql =
      select_job_sql(where.empty() ? "" : "WHERE " + where) + " ORDER BY id DESC LIMIT ?3";
  SqliteQuery q(connection(), sql);
  if (query.state) q.bind(1, to_string(*query.state));
  if (query.before_id) q.bind(2, *query.before_id);
  const int page_size = query.page_size < 1 ? 1 : query.page_size;
  q.bind(3, static_cast<std::int64_t>(page_size) + 1);  // one more tells whether a page follows
  JobPage page;
  while (q.step()) {
    if (static_cast<int>(page.jobs.size()) == page_size) {
      page.next_before_id = page.jobs.back().id;
      break;
    }
    page.jobs.push_back(read_job(q));
  }
  return page;
}

CancelOutcome SqliteJobStore::cancel(std::int64_t id) {
  SqliteConnection& c = connection();
  ImmediateTransaction tx(c);
  CancelOutcome out;
  const std::optional<JobState> state = state_of(c, id);
  if (!state) {
    out.kind = CancelOutcome::Kind::kNotFound;
    return out;
  }
  if (*state == JobState::kQueued) {
    SqliteQuery q(c,
                  "UPDATE jobs SET state = 'cancelled', cancel_requested = 1, finished_at = ? "
                  "WHERE id = ?");
    q.bind(1, now_unix_ms()).bind(2, id).run();
    out.kind = CancelOutcome::Kind::kCancelled;
  } else if (*state == JobState::kRunning) {
    SqliteQuery q(c, "UPDATE jobs SET cancel_requested = 1 WHERE id = ?");
    q.bind(1, id).run();
    out.kind = CancelOutcome::Kind::kRequested;
  } else {
    out.kind = CancelOutcome::Kind::kAlreadyFinished;
  }
  out.job = find_on(c, id);
  tx.commit();
  return out;
}

DeleteOutcome SqliteJobStore::remove(std::int64_t id) {
  SqliteConnection& c = connection();
  ImmediateTransaction tx(c);
  const std::optional<JobState> state = state_of(c, id);
  if (!state) return DeleteOutcome::kNotFound;
  if (!is_finished(*state)) return DeleteOutcome::kNotFinished;
  {
    SqliteQuery q(c, "DELETE FROM jobs WHERE id = ?");  // job_results cascade
    q.bind(1, id).run();
  }
  tx.commit();
  return DeleteOutcome::kDeleted;
}

std::optional<ClaimedJob> SqliteJobStore::claim_next() {
  SqliteConnection& c = connection();
  // Unlocked peek first: idle workers poll, and must not take the write lock to find nothing.
  {
    SqliteQuery q(c, "SELECT 1 FROM jobs WHERE state = 'queued' LIMIT 1");
    if (!q.step()) return std::nullopt;
  }
  ImmediateTransaction tx(c);
  ClaimedJob claimed;
  std::int64_t id = 0;
  {
    SqliteQuery q(c, "SELECT id, case_json FROM jobs WHERE state = 'queued' ORDER BY id LIMIT 1");
    if (!q.step()) return std::nullopt;  // another worker was faster
    id = q.int64(0);
    claimed.case_json = q.text(1);
  }
  {
    SqliteQuery q(c,
                  "UPDATE jobs SET state = 'running', attempts = attempts + 1, started_at = ?, "
                  "progress_iteration = NULL, progress_kkt_residual = NULL, "
                  "progress_energy = NULL WHERE id = ?");
    q.bind(1, now_unix_ms()).bind(2, id).run();
  }
  claimed.job = *find_on(c, id);
  tx.commit();
  return claimed;
}

void SqliteJobStore::update_progress(std::int64_t id, int attempt, const JobProgress& progress) {
  // A single autocommit statement: no transaction stays open while the solver runs.
  SqliteQuery q(connection(),
                "UPDATE jobs SET progress_iteration = ?, progress_kkt_residual = ?, "
                "progress_energy = ? WHERE id = ? AND state = 'running' AND attempts = ?");
  q.bind(1, static_cast<std::int64_t>(progress.iteration))
      .bind(2, progress.kkt_residual)
      .bind(3, progress.energy)
      .bind(4, id)
      .bind(5, static_cast<std::int64_t>(attempt));
  q.run();
}

bool SqliteJobStore::complete_succeeded(std::int64_t id, int attempt,
                                        const std::string& result_json, const std::string& vtu) {
  SqliteConnection& c = connection();
  ImmediateTransaction tx(c);
  const std::int64_t now = now_unix_ms();
  {
    SqliteQuery q(c,
                  "UPDATE jobs SET state = 'succeeded', finished_at = ?, error = NULL "
                  "WHERE id = ? AND state = 'running' AND attempts = ?");
    q.bind(1, now).bind(2, id).bind(3, static_cast<std::int64_t>(attempt)).run();
  }
  if (c.changes() == 0) return false;  // not this attempt's job any more
  {
    SqliteQuery q(c,
                  "INSERT INTO job_results (job_id, result_json, vtu, written_at) "
                  "VALUES (?, ?, ?, ?)");
    q.bind(1, id)
        .bind(2, std::string_view(result_json))
        .bind(3, std::string_view(vtu))
        .bind(4, now)
        .run();
  }
  tx.commit();
  return true;
}

bool SqliteJobStore::complete_failed(std::int64_t id, int attempt, const std::string& error) {
  SqliteConnection& c = connection();
  SqliteQuery q(c,
                "UPDATE jobs SET state = 'failed', finished_at = ?, error = ? "
                "WHERE id = ? AND state = 'running' AND attempts = ?");
  q.bind(1, now_unix_ms())
      .bind(2, std::string_view(error))
      .bind(3, id)
      .bind(4, static_cast<std::int64_t>(attempt))
      .run();
  return c.changes() > 0;
}

bool SqliteJobStore::complete_cancelled(std::int64_t id, int attempt) {
  SqliteConnection& c = connection();
  SqliteQuery q(c,
                "UPDATE jobs SET state = 'cancelled', finished_at = ? "
                "WHERE id = ? AND state = 'running' AND attempts = ?");
  q.bind(1, now_unix_ms()).bind(2, id).bind(3, static_cast<std::int64_t>(attempt)).run();
  return c.changes() > 0;
}

bool SqliteJobStore::requeue(std::int64_t id, int attempt) {
  SqliteConnection& c = connection();
  SqliteQuery q(c,
                "UPDATE jobs SET "
                "state = CASE WHEN cancel_requested THEN 'cancelled' ELSE 'queued' END, "
                "attempts = CASE WHEN cancel_requested THEN attempts ELSE attempts - 1 END, "
                "finished_at = CASE WHEN cancel_requested THEN ?1 ELSE NULL END, "
                "started_at = CASE WHEN cancel_requested THEN started_at ELSE NULL END "
                "WHERE id = ?2 AND state = 'running' AND attempts = ?3");
  q.bind(1, now_unix_ms()).bind(2, id).bind(3, static_cast<std::int64_t>(attempt)).run();
  return c.changes() > 0;
}

RecoveryReport SqliteJobStore::recover_interrupted(int max_attempts) {
  SqliteConnection& c = connection();
  ImmediateTransaction tx(c);
  RecoveryReport report;
  struct Interrupted {
    std::int64_t id;
    int attempts;
    bool cancel_requested;
  };
  std::vector<Interrupted> interrupted;
  {
    SqliteQuery q(c, "SELECT id, attempts, cancel_requested FROM jobs WHERE state = 'running'");
    while (q.step()) {
      interrupted.push_back({q.int64(0), static_cast<int>(q.int64(1)), q.int64(2) != 0});
    }
  }
  const std::int64_t now = now_unix_ms();
  for (const Interrupted& job : interrupted) {
    if (job.cancel_requested) {
      SqliteQuery q(c, "UPDATE jobs SET state = 'cancelled', finished_at = ? WHERE id = ?");
      q.bind(1, now).bind(2, job.id).run();
      report.cancelled.push_back(job.id);
    } else if (job.attempts >= max_attempts) {
      const std::string error = "the service stopped while solving this job " +
                                std::to_string(job.attempts) +
                                " times (limit --max-attempts); it is not retried again";
      SqliteQuery q(c, "UPDATE jobs SET state = 'failed', finished_at = ?, error = ? WHERE id = ?");
      q.bind(1, now).bind(2, std::string_view(error)).bind(3, job.id).run();
      report.failed.push_back(job.id);
    } else {
      SqliteQuery q(c,
                    "UPDATE jobs SET state = 'queued', started_at = NULL, "
                    "progress_iteration = NULL, progress_kkt_residual = NULL, "
                    "progress_energy = NULL WHERE id = ?");
      q.bind(1, job.id).run();
      report.requeued.push_back(job.id);
    }
  }
  tx.commit();
  return report;
}

int SqliteJobStore::delete_finished_before(std::int64_t unix_ms) {
  SqliteConnection& c = connection();
  int total = 0;
  // Small batches so the write lock (and the VTU text freed) is never held for long.
  for (;;) {
    SqliteQuery q(c,
                  "DELETE FROM jobs WHERE id IN (SELECT id FROM jobs WHERE finished_at IS NOT "
                  "NULL AND finished_at < ? AND state IN ('succeeded', 'failed', 'cancelled') "
                  "LIMIT 100)");
    q.bind(1, unix_ms).run();
    const auto n = c.changes();
    total += static_cast<int>(n);
    if (n < 100) break;
  }
  return total;
}

std::map<JobState, std::int64_t> SqliteJobStore::count_by_state() {
  std::map<JobState, std::int64_t> counts;
  for (JobState s : kAllJobStates) counts[s] = 0;
  SqliteQuery q(connection(), "SELECT state, count(*) FROM jobs GROUP BY state");
  while (q.step()) {
    if (auto s = parse_job_state(q.text(0))) counts[*s] = q.int64(1);
  }
  return counts;
}

void SqliteJobStore::ping() {
  SqliteQuery q(connection(), "SELECT 1");
  q.step();
}

}  // namespace fosls::service
