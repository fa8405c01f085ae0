#include "sqlite_job_store.hpp"

#include <filesystem>

#include "schema_migrations.hpp"

namespace fosls::service {

namespace {

// Version 1 is the schema of the first release (then versioned by PRAGMA user_version only).
// Results live in their own table so that listing jobs never reads result or VTU text, and
// job_id as primary key makes "a result is written once" a constraint, not a hope.
const std::vector<SchemaMigration> kSteps = {
    {1, "jobs and results", R"sql(
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
)sql"},
    // The VTU column keeps its declared type TEXT: SQLite stores a BLOB in it unchanged, and
    // this way existing results need not be copied. Old rows stay 'identity'.
    {2, "worker leases; gzip-compressed VTU", R"sql(
ALTER TABLE jobs ADD COLUMN lease_owner TEXT;
ALTER TABLE jobs ADD COLUMN lease_expires_at INTEGER;
CREATE INDEX jobs_running_by_lease ON jobs(lease_expires_at) WHERE state = 'running';
ALTER TABLE job_results ADD COLUMN vtu_encoding TEXT NOT NULL DEFAULT 'identity'
  CHECK (vtu_encoding IN ('identity', 'gzip'));
)sql"},
    // Copied from the result so that job listings show convergence without reading results;
    // jobs finished before this step get theirs from their stored result.
    {3, "convergence of finished solves", R"sql(
ALTER TABLE jobs ADD COLUMN converged INTEGER;
ALTER TABLE jobs ADD COLUMN stop_reason TEXT;
UPDATE jobs SET
  converged = (SELECT json_extract(r.result_json, '$.converged') FROM job_results r
               WHERE r.job_id = jobs.id AND json_valid(r.result_json)),
  stop_reason = (SELECT json_extract(r.result_json, '$.stop_reason') FROM job_results r
                 WHERE r.job_id = jobs.id AND json_valid(r.result_json));
CREATE INDEX jobs_not_converged ON jobs(id) WHERE converged = 0;
)sql"},
};

/// SQLite opens a 0-byte file as a new, empty database: a store truncated by accident (a full
/// disk, a copy gone wrong) would start over silently, and hand out job ids its clients still
/// hold for other jobs. A file that never existed is created; an emptied one is refused.
void refuse_emptied_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto bytes = fs::file_size(path, ec);
  if (ec || bytes != 0) return;
  const auto wal = fs::file_size(path + "-wal", ec);
  if (!ec && wal > 0) return;  // SQLite recovers the database from its write-ahead log
  throw StoreError("the database '" + path +
                   "' exists but is empty (0 bytes): it was truncated or never written, and "
                   "starting on it would lose its jobs and give their ids to new ones; move it "
                   "away (or delete it) to start a new store, or restore it from a backup");
}

}  // namespace

SqliteJobStore::SqliteJobStore(std::string path, int busy_timeout_ms)
    : SqlJobStore([this] {
        // Owned by the per-thread map; the handle only lends it.
        return SqlConnectionHandle(&thread_connection(), [](SqlConnection*) {});
      }),
      path_(std::move(path)),
      busy_timeout_ms_(busy_timeout_ms) {
  refuse_emptied_file(path_);
  migrate();
}

SqliteConnection& SqliteJobStore::thread_connection() {
  const std::thread::id me = std::this_thread::get_id();
  {
    std::lock_guard lock(connections_mutex_);
    if (const auto it = connections_.find(me); it != connections_.end()) return *it->second;
  }
  // Opened outside the lock: opening takes milliseconds (the file, WAL mode, pragmas), and 100
  // HTTP threads starting at once made every other thread, /healthz's among them, wait for all
  // of their openings (a 1.4 s /healthz under 100 new downloads).
  auto fresh = std::make_unique<SqliteConnection>(path_, busy_timeout_ms_);
  watch_disk(*fresh);
  std::lock_guard lock(connections_mutex_);
  auto& slot = connections_[me];
  if (!slot) slot = std::move(fresh);  // only this thread adds its own slot
  return *slot;
}

void SqliteJobStore::migrate() {
  SqliteConnection& c = thread_connection();
  SchemaHooks hooks;
  hooks.legacy_version = [](SqlConnection& conn) {
    return static_cast<int>(conn.query("PRAGMA user_version")[0].int64("user_version"));
  };
  // Older programs (and tools) read the version from the file header; keep it in step.
  hooks.after_steps = [](SqlConnection& conn, int version) {
    conn.exec("PRAGMA user_version = " + std::to_string(version));
  };
  migrate_schema(c, schema_steps(kSteps), hooks, "database '" + path_ + "'");
  // A file created before incremental auto-vacuum keeps its free pages forever; converting it
  // rewrites the file once (VACUUM, outside any transaction; it needs as much free disk as
  // the file's size). New files are created with it (SqliteConnection).
  if (c.query("PRAGMA auto_vacuum")[0].int64("auto_vacuum") != 2) {
    c.exec("PRAGMA auto_vacuum=INCREMENTAL");
    c.exec("VACUUM");
  }
}

std::optional<std::string> SqliteJobStore::stored_vtu_bytes(std::int64_t id, std::int64_t offset,
                                                            std::int64_t length) {
  // job_results.job_id is the table's rowid (INTEGER PRIMARY KEY).
  return thread_connection().read_blob("job_results", "vtu", id, offset, length);
}

std::optional<std::int64_t> SqliteJobStore::result_json_size(std::int64_t id) {
  return thread_connection().blob_size("job_results", "result_json", id);
}

std::optional<std::string> SqliteJobStore::result_json_bytes(std::int64_t id, std::int64_t offset,
                                                             std::int64_t length) {
  return thread_connection().read_blob("job_results", "result_json", id, offset, length);
}

void SqliteJobStore::after_delete(SqlConnection& c) {
  // Deleted results leave free pages; give them back to the file system now rather than
  // keeping a file as large as its largest day. Best effort: the delete itself is committed.
  try {
    c.query("PRAGMA incremental_vacuum");
  } catch (const StoreError&) {
  }
}

}  // namespace fosls::service
