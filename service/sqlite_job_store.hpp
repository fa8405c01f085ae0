#pragma once
// JobStore on an embedded SQLite database (zero set-up; one file plus its WAL), for one
// process: fosls-serve holds a lock on it (main.cpp) and recovers all running jobs at start.

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "sql_job_store.hpp"
#include "sqlite_connection.hpp"

namespace fosls::service {

/// SQLite job store. Each calling thread gets its own connection (SQLite connections must not
/// be shared between threads); writes take the database's write lock at once (BEGIN
/// IMMEDIATE). Deleting jobs returns their pages to the file system (incremental vacuum).
class SqliteJobStore final : public SqlJobStore {
 public:
  /// Opens (creating if needed) the database at `path` and brings its schema to the current
  /// version, converting an older file to incremental auto-vacuum. Throws StoreError.
  explicit SqliteJobStore(std::string path, int busy_timeout_ms = 5000);

  /// Read without loading the rest of the value (SQL's substr would load all of it for each
  /// part); sizes in bytes also of text, which SQLite 3.40's length() counts in characters.
  std::optional<std::string> stored_vtu_bytes(std::int64_t id, std::int64_t offset,
                                              std::int64_t length) override;
  std::optional<std::int64_t> result_json_size(std::int64_t id) override;
  std::optional<std::string> result_json_bytes(std::int64_t id, std::int64_t offset,
                                               std::int64_t length) override;

 protected:
  void after_delete(SqlConnection& c) override;

 private:
  /// This thread's connection, opened on first use.
  SqliteConnection& thread_connection();
  void migrate();

  std::string path_;
  int busy_timeout_ms_;
  std::mutex connections_mutex_;
  // Keyed by thread: a thread id is only reused after its thread ended, so a connection is
  // never used by two threads at once.
  std::map<std::thread::id, std::unique_ptr<SqliteConnection>> connections_;
};

}  // namespace fosls::service
