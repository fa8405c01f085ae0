#pragma once
// What the job store needs from a SQL connection, the same for SQLite and PostgreSQL:
// parameterised statements that return rows, and write transactions. The store's SQL is
// written once (sql_job_store.cpp) with ?1, ?2, ... parameters and two tokens that each
// connection spells in its own dialect (translate_sql).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace fosls::service {

/// Bytes stored as BLOB (SQLite) or bytea (PostgreSQL) rather than text.
struct SqlBlob {
  std::string bytes;
};

/// A statement parameter or a column value; std::monostate is SQL NULL.
using SqlValue = std::variant<std::monostate, std::int64_t, double, std::string, SqlBlob>;

/// A parameter that is NULL when absent.
SqlValue sql_optional(const std::optional<std::string>& value);

/// The column names of a result, shared by its rows.
using SqlColumnNames = std::shared_ptr<const std::vector<std::string>>;

/// One result row, read by column name (as the statement's select list or RETURNING clause
/// names it; give expressions a name with AS). Reading NULL gives 0, NaN or "" (check is_null).
/// A name the row does not have throws StoreError.
class SqlRow {
 public:
  SqlRow(SqlColumnNames names, std::vector<SqlValue> values)
      : names_(std::move(names)), values_(std::move(values)) {}

  bool is_null(std::string_view column) const;
  std::int64_t int64(std::string_view column) const;
  double real(std::string_view column) const;
  /// Text, or the bytes of a blob.
  std::string text(std::string_view column) const;
  std::optional<std::int64_t> optional_int64(std::string_view column) const;

 private:
  const SqlValue& at(std::string_view column) const;
  SqlColumnNames names_;
  std::vector<SqlValue> values_;
};

using SqlRows = std::vector<SqlRow>;

/// The SQL spoken by a connection, for the few places where the dialects differ.
enum class SqlDialect { kSqlite, kPostgres };

/// Rewrites the store's SQL for a dialect: {now_ms} becomes the database clock in Unix
/// milliseconds, {skip_locked} becomes FOR UPDATE SKIP LOCKED (PostgreSQL) or nothing (SQLite
/// serialises writers), and ?N becomes $N for PostgreSQL.
std::string translate_sql(SqlDialect dialect, const std::string& sql);

/// One connection, used by one thread at a time. Errors are thrown as StoreError.
class SqlConnection {
 public:
  virtual ~SqlConnection() = default;

  virtual SqlDialect dialect() const = 0;

  /// Runs one statement (store SQL, see translate_sql) with parameters ?1, ?2, ... and returns
  /// its rows (those of RETURNING for writes).
  virtual SqlRows query(const std::string& sql, const std::vector<SqlValue>& params = {}) = 0;

  /// Runs dialect SQL without parameters or results; several statements are allowed.
  virtual void exec(const std::string& sql) = 0;

  /// Starts a transaction that will write. SQLite takes the write lock at once (BEGIN
  /// IMMEDIATE), so a read-then-write never fails half way with SQLITE_BUSY_SNAPSHOT.
  virtual void begin_write() = 0;
  virtual void commit() = 0;
  /// Undoes the open transaction; never throws.
  virtual void rollback() noexcept = 0;

  /// False once the connection is broken (the server went away); it is then discarded.
  virtual bool usable() const { return true; }

  /// Rows inserted, updated or deleted through this connection so far: a commit is proof that
  /// the disk has room only when its transaction wrote something.
  virtual std::int64_t rows_changed() const = 0;

  /// Told of every statement that failed because the disk is full (`full`, with the message,
  /// before StoreFullError is thrown) and of every commit that went through having written rows
  /// (not `full`), so that the store can tell whether it can write. A commit that wrote nothing
  /// (the lease reaper's, when no lease expired) says nothing: it goes through on a full disk.
  void observe_disk(std::function<void(bool full, const std::string& message)> observer) {
    disk_observer_ = std::move(observer);
  }
  /// For SqlTransaction: a commit went through, so the disk took its writes.
  void committed() const {
    if (disk_observer_) disk_observer_(false, {});
  }

 protected:
  /// Tells the observer, then throws StoreFullError.
  [[noreturn]] void fail_disk_full(const std::string& message) const;

 private:
  std::function<void(bool full, const std::string& message)> disk_observer_;
};

/// begin_write ... commit; rolls back when destroyed uncommitted (for example when a
/// statement throws).
class SqlTransaction {
 public:
  explicit SqlTransaction(SqlConnection& connection) : connection_(connection) {
    connection_.begin_write();
    rows_changed_at_begin_ = connection_.rows_changed();
  }
  ~SqlTransaction() {
    if (open_) connection_.rollback();
  }
  SqlTransaction(const SqlTransaction&) = delete;
  SqlTransaction& operator=(const SqlTransaction&) = delete;

  void commit() {
    connection_.commit();
    open_ = false;
    if (connection_.rows_changed() != rows_changed_at_begin_) connection_.committed();
  }

 private:
  SqlConnection& connection_;
  bool open_ = true;
  std::int64_t rows_changed_at_begin_ = 0;
};

/// A connection lent to one call; the deleter gives it back to where it came from.
using SqlConnectionHandle = std::unique_ptr<SqlConnection, std::function<void(SqlConnection*)>>;

}  // namespace fosls::service
