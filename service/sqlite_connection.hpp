#pragma once
// SqlConnection on one SQLite connection: the pragmas every connection needs, prepared
// statements compiled once, BEGIN IMMEDIATE for writes. Errors become StoreError.

#include <sqlite3.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "sql_connection.hpp"

namespace fosls::service {

/// One connection, to be used by one thread at a time. Opening it applies incremental
/// auto-vacuum (effective when the file is new), WAL mode, busy_timeout, synchronous=FULL,
/// foreign_keys and a bound on the WAL file left after a checkpoint (SQLite defaults none of
/// them).
class SqliteConnection final : public SqlConnection {
 public:
  SqliteConnection(const std::string& path, int busy_timeout_ms);
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;

  SqlDialect dialect() const override { return SqlDialect::kSqlite; }
  SqlRows query(const std::string& sql, const std::vector<SqlValue>& params = {}) override;
  void exec(const std::string& sql) override;
  void begin_write() override { exec("BEGIN IMMEDIATE"); }
  void commit() override { exec("COMMIT"); }
  void rollback() noexcept override;
  std::int64_t rows_changed() const override { return sqlite3_total_changes64(db_.get()); }

  /// Up to `length` bytes from `offset` of the BLOB or TEXT value in `column` of the row
  /// `rowid` of `table`, read without loading the rest of the value (incremental blob I/O, its
  /// own short read transaction); nothing when the row is gone.
  std::optional<std::string> read_blob(const char* table, const char* column, std::int64_t rowid,
                                       std::int64_t offset, std::int64_t length);
  /// The size in bytes of that value, read without loading it; nothing when the row is gone.
  std::optional<std::int64_t> blob_size(const char* table, const char* column, std::int64_t rowid);

  /// Throws StoreError naming `what` and SQLite's message.
  [[noreturn]] void fail(int code, std::string_view what) const;

 private:
  struct CloseDb {
    void operator()(sqlite3* db) const { sqlite3_close_v2(db); }
  };
  struct FinalizeStmt {
    void operator()(sqlite3_stmt* s) const { sqlite3_finalize(s); }
  };
  /// The prepared statement for store SQL `sql`, compiled once per connection.
  sqlite3_stmt& statement(const std::string& sql);
  void bind(sqlite3_stmt& stmt, int index, const SqlValue& value);

  // Statements are finalized before the connection closes (members destroy in reverse).
  std::unique_ptr<sqlite3, CloseDb> db_;
  std::unordered_map<std::string, std::unique_ptr<sqlite3_stmt, FinalizeStmt>> statements_;
};

}  // namespace fosls::service
