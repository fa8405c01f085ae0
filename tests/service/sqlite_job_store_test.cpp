// What only the SQLite store has (the shared contract is job_store_contract_test.cpp): WAL
// mode, the schema version in the file header, migration of a first-release file, space given
// back when jobs are deleted, compressed VTU.

#include "sqlite_job_store.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "store_test_support.hpp"

namespace fosls::service {
namespace {

using testing::claim_as;
using testing::kUnlimited;
using testing::make_job;
using testing::TempDir;

/// Runs SQL on the file with a separate plain connection; returns the first column of the
/// first row (or 0).
std::int64_t sql_int(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_busy_timeout(db, 5000);
  sqlite3_stmt* stmt = nullptr;
  std::int64_t out = 0;
  EXPECT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr), SQLITE_OK) << sql;
  if (sqlite3_step(stmt) == SQLITE_ROW) out = sqlite3_column_int64(stmt, 0);
  sqlite3_finalize(stmt);
  sqlite3_close(db);
  return out;
}

void sql_exec(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  char* error = nullptr;
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK)
      << (error ? error : "") << "\n"
      << sql;
  sqlite3_close(db);
}

/// Text that does not compress (so that page counts measure the rows).
std::string random_text(std::size_t n) {
  std::mt19937 rng(7);
  std::string s(n, ' ');
  for (char& c : s) c = static_cast<char>('a' + rng() % 26);
  return s;
}

TEST(SqliteJobStore, DatabaseIsInWalMode) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  SqliteJobStore store(path);
  store.submit(make_job("1"), kUnlimited);
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "PRAGMA journal_mode", -1, &stmt, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(stmt), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0)), "wal");
  sqlite3_finalize(stmt);
  sqlite3_close(db);
}

TEST(SqliteJobStore, SchemaFromANewerProgramIsRefused) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  { SqliteJobStore store(path); }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "PRAGMA user_version = 99", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  EXPECT_THROW(SqliteJobStore store(path), StoreError);
}

TEST(SqliteJobStore, NewerVersionInTheMigrationTableIsRefused) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  { SqliteJobStore store(path); }
  sql_exec(path, "INSERT INTO schema_migrations VALUES (99, 'from the future', 0)");
  try {
    SqliteJobStore store(path);
    FAIL() << "opened a database of schema version 99";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("schema version 99"), std::string::npos) << e.what();
  }
}

TEST(SqliteJobStore, UnwritableLocationIsAStoreError) {
  EXPECT_THROW(SqliteJobStore store("/proc/no/such/folder/jobs.db"), StoreError);
}

TEST(SqliteJobStore, NewDatabaseRecordsItsVersionAndVacuumsIncrementally) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  { SqliteJobStore store(path); }
  // 1–3 SQLite's own steps, 4 to 6 the steps both stores share (worker budgets, progress
  // steps, time estimates).
  EXPECT_EQ(sql_int(path, "SELECT max(version) FROM schema_migrations"), 6);
  EXPECT_EQ(sql_int(path, "PRAGMA user_version"), 6);
  EXPECT_EQ(sql_int(path, "PRAGMA auto_vacuum"), 2);  // incremental
  { SqliteJobStore again(path); }                     // opening again changes nothing
  EXPECT_EQ(sql_int(path, "SELECT count(*) FROM schema_migrations"), 6);
}

// A file written by the first release (schema version 1, no auto-vacuum, VTU as text, a job
// left running by a crash) is migrated on open: nothing is lost and everything works.
TEST(SqliteJobStore, MigratesAFirstReleaseDatabase) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  sql_exec(path, R"sql(
PRAGMA journal_mode=WAL;
CREATE TABLE jobs (
  id INTEGER PRIMARY KEY AUTOINCREMENT, name TEXT NOT NULL,
  state TEXT NOT NULL CHECK (state IN ('queued', 'running', 'succeeded', 'failed', 'cancelled')),
  case_json TEXT NOT NULL, idempotency_key TEXT UNIQUE, body_hash TEXT NOT NULL, error TEXT,
  progress_iteration INTEGER, progress_kkt_residual REAL, progress_energy REAL,
  attempts INTEGER NOT NULL DEFAULT 0, cancel_requested INTEGER NOT NULL DEFAULT 0,
  created_at INTEGER NOT NULL, started_at INTEGER, finished_at INTEGER);
CREATE INDEX jobs_by_state ON jobs(state, id);
CREATE INDEX jobs_by_finished_at ON jobs(finished_at) WHERE finished_at IS NOT NULL;
CREATE TABLE job_results (
  job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,
  result_json TEXT NOT NULL, vtu TEXT NOT NULL, written_at INTEGER NOT NULL);
INSERT INTO jobs (name, state, case_json, body_hash, attempts, created_at, started_at, finished_at)
  VALUES ('old', 'succeeded', '{}', 'h', 1, 1000, 1100, 1200),
         ('interrupted', 'running', '{"b":2}', 'h2', 1, 1000, 1100, NULL);
INSERT INTO job_results
  VALUES (1, '{"old":true,"converged":false,"stop_reason":"max_iterations"}',
          '<VTKFile old="1"/>', 1200);
PRAGMA user_version = 1;
)sql");
  ASSERT_EQ(sql_int(path, "PRAGMA auto_vacuum"), 0);

  SqliteJobStore store(path);
  EXPECT_EQ(sql_int(path, "PRAGMA auto_vacuum"), 2);  // converted by VACUUM
  EXPECT_EQ(sql_int(path, "SELECT max(version) FROM schema_migrations"), 6);
  EXPECT_EQ(store.result_json(1),
            R"({"old":true,"converged":false,"stop_reason":"max_iterations"})");
  // Convergence is copied from results stored before the columns existed.
  EXPECT_EQ(store.find(1)->convergence.converged, std::optional<bool>(false));
  EXPECT_EQ(store.find(1)->convergence.stop_reason, "max_iterations");
  EXPECT_FALSE(store.find(2)->convergence.converged);
  EXPECT_EQ(store.count_not_converged(), 1);
  EXPECT_EQ(store.vtu(1), R"(<VTKFile old="1"/>)");  // uncompressed rows stay readable
  const RecoveryReport report = store.recover_interrupted(3);
  EXPECT_EQ(report.requeued, std::vector<std::int64_t>{2});
  const auto claimed = store.claim_next(claim_as());
  ASSERT_TRUE(claimed);
  EXPECT_EQ(claimed->job.id, 2);
  EXPECT_EQ(claimed->job.attempts, 2);
  store.update_progress(claimed->lease, JobProgress{3, 0.1, -1.0, 1, 2});
  EXPECT_EQ(store.find(2)->progress->steps, 2);
  EXPECT_TRUE(store.complete_succeeded(claimed->lease, "{}", "<VTKFile new=\"1\"/>"));
  EXPECT_EQ(store.vtu(2), "<VTKFile new=\"1\"/>");
  EXPECT_EQ(store.submit(make_job("3"), kUnlimited).job->id, 3);
}

TEST(SqliteJobStore, VtuIsStoredCompressed) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  SqliteJobStore store(path);
  const auto id = store.submit(make_job("1"), kUnlimited).job->id;
  std::string vtu;
  for (int i = 0; i < 20000; ++i) vtu += "<DataArray>" + std::to_string(i * 0.5) + "</DataArray>\n";
  ASSERT_TRUE(store.complete_succeeded(store.claim_next(claim_as())->lease, "{}", vtu));
  EXPECT_EQ(store.vtu(id), vtu);
  const auto stored = sql_int(path, "SELECT length(vtu) FROM job_results");
  EXPECT_EQ(sql_int(path, "SELECT vtu_encoding = 'gzip' FROM job_results"), 1);
  EXPECT_LT(stored * 4, static_cast<std::int64_t>(vtu.size())) << stored << " of " << vtu.size();
}

TEST(SqliteJobStore, CorruptCompressedVtuIsAStoreErrorNotACrash) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  SqliteJobStore store(path);
  const auto id = store.submit(make_job("1"), kUnlimited).job->id;
  ASSERT_TRUE(store.complete_succeeded(store.claim_next(claim_as())->lease, "{}", "<VTKFile/>"));
  sql_exec(path, "UPDATE job_results SET vtu = substr(vtu, 1, 8)");
  EXPECT_THROW(store.vtu(id), StoreError);
}

// Deleting jobs (by the API or by retention) gives their pages back to the file system.
TEST(SqliteJobStore, DeletingJobsReturnsTheirSpace) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  SqliteJobStore store(path);
  const std::int64_t empty_pages = sql_int(path, "PRAGMA page_count");
  std::vector<std::int64_t> ids;
  for (int i = 0; i < 3; ++i) {
    ids.push_back(store.submit(make_job(std::to_string(i)), kUnlimited).job->id);
    ASSERT_TRUE(store.complete_succeeded(store.claim_next(claim_as())->lease, "{}",
                                         random_text(2'000'000)));
  }
  const std::int64_t full_pages = sql_int(path, "PRAGMA page_count");
  EXPECT_GT(full_pages, empty_pages + 3 * 300);  // about 1.2 MB each after compression
  EXPECT_EQ(store.remove(ids[0]), DeleteOutcome::kDeleted);
  EXPECT_EQ(sql_int(path, "PRAGMA freelist_count"), 0);
  EXPECT_LT(sql_int(path, "PRAGMA page_count"), full_pages - 250);
  EXPECT_EQ(store.delete_finished_before(now_unix_ms() + 1'000'000), 2);
  EXPECT_EQ(sql_int(path, "PRAGMA freelist_count"), 0);
  EXPECT_LT(sql_int(path, "PRAGMA page_count"), empty_pages + 20);
  // After a checkpoint the file itself is that small.
  sql_exec(path, "PRAGMA wal_checkpoint(TRUNCATE)");
  EXPECT_LT(std::filesystem::file_size(path), static_cast<std::uintmax_t>(1 << 20));
}

}  // namespace
}  // namespace fosls::service

namespace fosls::service {
namespace {

TEST(SqliteJobStore, AnEmptiedFileIsRefusedAndANewOneCreated) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  std::ofstream(path).close();
  EXPECT_THROW(SqliteJobStore{path}, StoreError);
  std::filesystem::remove(path);
  SqliteJobStore created(path);  // a file that never existed is created
  EXPECT_EQ(created.submit(make_job("1"), kUnlimited).job->id, 1);
}

TEST(SqliteConnection, AFullDiskIsStoreFullErrorAndTheObserverHearsOfIt) {
  // SQLite answers SQLITE_FULL when a database reaches max_page_count, as when the disk has no
  // room: the same error path, without filling a disk.
  TempDir dir;
  SqliteConnection c(dir.file("full.db"), 5000);
  std::vector<std::pair<bool, std::string>> heard;
  c.observe_disk([&](bool full, const std::string& message) { heard.emplace_back(full, message); });
  c.exec("CREATE TABLE t (x TEXT)");
  c.exec("PRAGMA max_page_count = 40");
  bool full = false;
  for (int i = 0; i < 200 && !full; ++i) {
    try {
      c.query("INSERT INTO t (x) VALUES (?1)", {random_text(2000)});
    } catch (const StoreFullError& e) {
      full = true;
      EXPECT_NE(std::string(e.what()).find("full"), std::string::npos) << e.what();
    }
  }
  ASSERT_TRUE(full) << "the page limit was never reached";
  ASSERT_FALSE(heard.empty());
  EXPECT_TRUE(heard.back().first);
  // A commit that wrote nothing goes through even on a full disk (the lease reaper makes one
  // whenever no lease expired): it is no proof of room, so the observer hears nothing.
  const auto heard_before = heard.size();
  {
    SqlTransaction tx(c);
    c.query("SELECT count(*) FROM t");
    c.query("DELETE FROM t WHERE x = 'no such row'");
    tx.commit();
  }
  EXPECT_EQ(heard.size(), heard_before);
  // A commit that wrote rows tells the observer the disk took it.
  c.exec("DELETE FROM t");
  {
    SqlTransaction tx(c);
    c.query("INSERT INTO t (x) VALUES ('small')");
    tx.commit();
  }
  EXPECT_FALSE(heard.back().first);
}

}  // namespace
}  // namespace fosls::service
