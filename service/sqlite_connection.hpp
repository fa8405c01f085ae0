#pragma once
// A thin RAII layer over one SQLite connection: pragmas every connection needs, cached
// prepared statements, and BEGIN IMMEDIATE transactions. Errors become StoreError.

#include <sqlite3.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

namespace fosls::service {

/// One connection, to be used by one thread at a time. Opening it applies WAL mode,
/// busy_timeout, synchronous=FULL and foreign_keys (SQLite defaults none of them).
class SqliteConnection {
 public:
  SqliteConnection(const std::string& path, int busy_timeout_ms);
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;

  /// Runs SQL without results (several statements allowed).
  void exec(const char* sql);

  /// A prepared statement for `sql`, compiled once per connection.
  sqlite3_stmt& statement(const std::string& sql);

  /// Rows changed by the last INSERT, UPDATE or DELETE.
  std::int64_t changes() const;

  std::int64_t last_insert_rowid() const;

  /// Throws StoreError naming `what` and SQLite's message.
  [[noreturn]] void fail(int code, std::string_view what) const;

 private:
  struct CloseDb {
    void operator()(sqlite3* db) const { sqlite3_close_v2(db); }
  };
  struct FinalizeStmt {
    void operator()(sqlite3_stmt* s) const { sqlite3_finalize(s); }
  };
  // Statements are finalized before the connection closes (members destroy in reverse).
  std::unique_ptr<sqlite3, CloseDb> db_;
  std::unordered_map<std::string, std::unique_ptr<sqlite3_stmt, FinalizeStmt>> statements_;
};

/// One use of a cached statement: bind, step, read columns; resets it when it goes out of
/// scope so the connection holds no open read.
class SqliteQuery {
 public:
  SqliteQuery(SqliteConnection& connection, const std::string& sql);
  ~SqliteQuery();
  SqliteQuery(const SqliteQuery&) = delete;
  SqliteQuery& operator=(const SqliteQuery&) = delete;

  /// Binds parameter `index` (1-based); text is copied.
  SqliteQuery& bind(int index, std::int64_t value);
  SqliteQuery& bind(int index, double value);
  SqliteQuery& bind(int index, std::string_view value);
  SqliteQuery& bind(int index, const std::string& value) {
    return bind(index, std::string_view(value));
  }
  SqliteQuery& bind_null(int index);
  SqliteQuery& bind(int index, const std::optional<std::int64_t>& value);
  SqliteQuery& bind(int index, const std::optional<std::string>& value);

  /// Advances to the next row; false when there is none.
  bool step();

  /// Runs a statement that returns no rows.
  void run();

  bool is_null(int column) const;
  std::int64_t int64(int column) const;
  double real(int column) const;
  std::string text(int column) const;
  std::optional<std::int64_t> optional_int64(int column) const;

 private:
  SqliteConnection& connection_;
  sqlite3_stmt& stmt_;
};

/// BEGIN IMMEDIATE ... COMMIT; rolls back when destroyed uncommitted (for example when a
/// statement throws). Immediate, so that a read-then-write never fails with
/// SQLITE_BUSY_SNAPSHOT: the write lock is taken (waiting up to busy_timeout) before the read.
class ImmediateTransaction {
 public:
  explicit ImmediateTransaction(SqliteConnection& connection);
  ~ImmediateTransaction();
  ImmediateTransaction(const ImmediateTransaction&) = delete;
  ImmediateTransaction& operator=(const ImmediateTransaction&) = delete;

  void commit();

 private:
  SqliteConnection& connection_;
  bool open_ = true;
};

}  // namespace fosls::service
