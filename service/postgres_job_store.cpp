#include "postgres_job_store.hpp"

#include "schema_migrations.hpp"

namespace fosls::service {

namespace {

// Advisory lock keys (arbitrary constants, unique to this program's database).
constexpr std::int64_t kSchemaLock = 0x666f736c7301;  // "fosls" 1
constexpr std::int64_t kSubmitLock = 0x666f736c7302;

// The same contract as the SQLite schema (sqlite_job_store.cpp) at its latest version.
// Times are Unix milliseconds of the database clock; cancel_requested is an integer so that
// the store's SQL is the same text in both dialects.
const std::vector<SchemaMigration> kSteps = {
    {1, "jobs, results, worker leases", R"sql(
CREATE TABLE jobs (
  id BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
  name TEXT NOT NULL,
  state TEXT NOT NULL
    CHECK (state IN ('queued', 'running', 'succeeded', 'failed', 'cancelled')),
  case_json TEXT NOT NULL,
  idempotency_key TEXT UNIQUE,
  body_hash TEXT NOT NULL,
  error TEXT,
  progress_iteration BIGINT,
  progress_kkt_residual DOUBLE PRECISION,
  progress_energy DOUBLE PRECISION,
  attempts INTEGER NOT NULL DEFAULT 0,
  cancel_requested INTEGER NOT NULL DEFAULT 0,
  created_at BIGINT NOT NULL,
  started_at BIGINT,
  finished_at BIGINT,
  lease_owner TEXT,
  lease_expires_at BIGINT
);
CREATE INDEX jobs_by_state ON jobs(state, id);
CREATE INDEX jobs_by_finished_at ON jobs(finished_at) WHERE finished_at IS NOT NULL;
CREATE INDEX jobs_running_by_lease ON jobs(lease_expires_at) WHERE state = 'running';
CREATE TABLE job_results (
  job_id BIGINT PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,
  result_json TEXT NOT NULL,
  vtu BYTEA NOT NULL,
  vtu_encoding TEXT NOT NULL CHECK (vtu_encoding IN ('identity', 'gzip')),
  written_at BIGINT NOT NULL
);
-- Already gzip-compressed: out of line, without TOAST trying to compress it again.
ALTER TABLE job_results ALTER COLUMN vtu SET STORAGE EXTERNAL;
)sql"},
    // As SQLite's step 3: copied from the result, for listings that never read results.
    {2, "convergence of finished solves", R"sql(
ALTER TABLE jobs ADD COLUMN converged INTEGER;
ALTER TABLE jobs ADD COLUMN stop_reason TEXT;
UPDATE jobs SET converged = (r.result_json::jsonb->>'converged')::boolean::integer,
                stop_reason = r.result_json::jsonb->>'stop_reason'
  FROM job_results r
  WHERE r.job_id = jobs.id AND jsonb_typeof(r.result_json::jsonb->'converged') = 'boolean';
CREATE INDEX jobs_not_converged ON jobs(id) WHERE converged = 0;
)sql"},
};

}  // namespace

PostgresJobStore::PostgresJobStore(std::string conninfo, int max_connections)
    : SqlJobStore([this] { return borrow(); }),
      conninfo_(std::move(conninfo)),
      max_connections_(std::max(1, max_connections)) {
  migrate();
}

SqlConnectionHandle PostgresJobStore::borrow() {
  std::unique_lock lock(mutex_);
  returned_.wait(lock, [&] { return !idle_.empty() || open_ < max_connections_; });
  if (!idle_.empty()) {
    std::unique_ptr<SqlConnection> c = std::move(idle_.back());
    idle_.pop_back();
    return SqlConnectionHandle(c.release(), [this](SqlConnection* p) { give_back(p); });
  }
  ++open_;
  lock.unlock();
  try {
    auto* opened = new PostgresConnection(conninfo_);
    watch_disk(*opened);
    return SqlConnectionHandle(opened, [this](SqlConnection* p) { give_back(p); });
  } catch (...) {
    std::lock_guard relock(mutex_);
    --open_;
    returned_.notify_one();
    throw;
  }
}

void PostgresJobStore::give_back(SqlConnection* c) {
  std::unique_ptr<SqlConnection> owned(c);
  std::lock_guard lock(mutex_);
  if (owned->usable()) {
    idle_.push_back(std::move(owned));
  } else {
    --open_;  // dropped; the next borrower opens a fresh one
  }
  returned_.notify_one();
}

void PostgresJobStore::migrate() {
  auto c = borrow();
  SchemaHooks hooks;
  // Several API and worker processes may start at once on a new database.
  hooks.lock = [](SqlConnection& conn) {
    conn.query("SELECT pg_advisory_xact_lock(?1)", {kSchemaLock});
  };
  migrate_schema(*c, schema_steps(kSteps), hooks, "the PostgreSQL database");
}

std::optional<std::int64_t> PostgresJobStore::result_json_size(std::int64_t id) {
  const SqlRows rows = connection()->query(
      "SELECT octet_length(convert_to(result_json, 'UTF8')) AS bytes FROM job_results "
      "WHERE job_id = ?1",
      {id});
  if (rows.empty()) return std::nullopt;
  return rows[0].int64("bytes");
}

std::optional<std::string> PostgresJobStore::result_json_bytes(std::int64_t id, std::int64_t offset,
                                                               std::int64_t length) {
  // Each part converts the whole (compressed) text: results are small next to VTUs, which are
  // stored uncompressed and read by the part (SqlJobStore::stored_vtu_bytes).
  const SqlRows rows = connection()->query(
      "SELECT substr(convert_to(result_json, 'UTF8'), ?2, ?3) AS part FROM job_results "
      "WHERE job_id = ?1",
      {id, offset + 1, length});
  if (rows.empty()) return std::nullopt;
  return rows[0].text("part");
}

void PostgresJobStore::serialize_submits(SqlConnection& c) {
  // Held until the submit commits: the queue count and the idempotency key check then see
  // every earlier submit, from any process, as SQLite's write lock guarantees.
  c.query("SELECT pg_advisory_xact_lock(?1)", {kSubmitLock});
}

}  // namespace fosls::service
