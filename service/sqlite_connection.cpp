#include "sqlite_connection.hpp"

#include <string>

#include "job_store.hpp"

namespace fosls::service {

SqliteConnection::SqliteConnection(const std::string& path, int busy_timeout_ms) {
  sqlite3* raw = nullptr;
  // NOMUTEX: each connection is used by one thread at a time, so SQLite's own locking of the
  // connection is redundant.
  const int rc =
      sqlite3_open_v2(path.c_str(), &raw,
                      SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX, nullptr);
  db_.reset(raw);  // even on failure the handle must be closed
  if (rc != SQLITE_OK) fail(rc, "opening database '" + path + "'");
  sqlite3_extended_result_codes(db_.get(), 1);
  sqlite3_busy_timeout(db_.get(), busy_timeout_ms);
  exec("PRAGMA journal_mode=WAL");
  exec("PRAGMA synchronous=FULL");
  exec("PRAGMA foreign_keys=ON");
}

void SqliteConnection::exec(const char* sql) {
  char* message = nullptr;
  const int rc = sqlite3_exec(db_.get(), sql, nullptr, nullptr, &message);
  if (rc != SQLITE_OK) {
    std::string text = message ? message : sqlite3_errstr(rc);
    sqlite3_free(message);
    throw StoreError(std::string(sql) + ": " + text);
  }
}

sqlite3_stmt& SqliteConnection::statement(const std::string& sql) {
  auto it = statements_.find(sql);
  if (it != statements_.end()) return *it->second;
  sqlite3_stmt* raw = nullptr;
  const int rc = sqlite3_prepare_v3(db_.get(), sql.c_str(), static_cast<int>(sql.size()),
                                    SQLITE_PREPARE_PERSISTENT, &raw, nullptr);
  std::unique_ptr<sqlite3_stmt, FinalizeStmt> stmt(raw);
  if (rc != SQLITE_OK) fail(rc, "preparing '" + sql + "'");
  sqlite3_stmt& ref = *stmt;
  statements_.emplace(sql, std::move(stmt));
  return ref;
}

std::int64_t SqliteConnection::changes() const { return sqlite3_changes64(db_.get()); }

std::int64_t SqliteConnection::last_insert_rowid() const {
  return sqlite3_last_insert_rowid(db_.get());
}

void SqliteConnection::fail(int code, std::string_view what) const {
  std::string message = std::string(what) + ": ";
  message += db_ ? sqlite3_errmsg(db_.get()) : sqlite3_errstr(code);
  message += " (SQLite code " + std::to_string(code) + ")";
  throw StoreError(message);
}

SqliteQuery::SqliteQuery(SqliteConnection& connection, const std::string& sql)
    : connection_(connection), stmt_(connection.statement(sql)) {}

SqliteQuery::~SqliteQuery() {
  sqlite3_reset(&stmt_);
  sqlite3_clear_bindings(&stmt_);
}

SqliteQuery& SqliteQuery::bind(int index, std::int64_t value) {
  const int rc = sqlite3_bind_int64(&stmt_, index, value);
  if (rc != SQLITE_OK) connection_.fail(rc, "binding a parameter");
  return *this;
}

SqliteQuery& SqliteQuery::bind(int index, double value) {
  const int rc = sqlite3_bind_double(&stmt_, index, value);
  if (rc != SQLITE_OK) connection_.fail(rc, "binding a parameter");
  return *this;
}

SqliteQuery& SqliteQuery::bind(int index, std::string_view value) {
  const int rc =
      sqlite3_bind_text64(&stmt_, index, value.data(), value.size(), SQLITE_TRANSIENT, SQLITE_UTF8);
  if (rc != SQLITE_OK) connection_.fail(rc, "binding a parameter");
  return *this;
}

SqliteQuery& SqliteQuery::bind_null(int index) {
  const int rc = sqlite3_bind_null(&stmt_, index);
  if (rc != SQLITE_OK) connection_.fail(rc, "binding a parameter");
  return *this;
}

SqliteQuery& SqliteQuery::bind(int index, const std::optional<std::int64_t>& value) {
  return value ? bind(index, *value) : bind_null(index);
}

SqliteQuery& SqliteQuery::bind(int index, const std::optional<std::string>& value) {
  return value ? bind(index, std::string_view(*value)) : bind_null(index);
}

bool SqliteQuery::step() {
  const int rc = sqlite3_step(&stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  connection_.fail(rc, std::string("running '") + sqlite3_sql(&stmt_) + "'");
}

void SqliteQuery::run() {
  while (step()) {
  }
}

bool SqliteQuery::is_null(int column) const {
  return sqlite3_column_type(&stmt_, column) == SQLITE_NULL;
}

std::int64_t SqliteQuery::int64(int column) const { return sqlite3_column_int64(&stmt_, column); }

double SqliteQuery::real(int column) const { return sqlite3_column_double(&stmt_, column); }

std::string SqliteQuery::text(int column) const {
  const auto* data = reinterpret_cast<const char*>(sqlite3_column_text(&stmt_, column));
  if (!data) return {};
  return std::string(data, static_cast<std::size_t>(sqlite3_column_bytes(&stmt_, column)));
}

std::optional<std::int64_t> SqliteQuery::optional_int64(int column) const {
  if (is_null(column)) return std::nullopt;
  return int64(column);
}

ImmediateTransaction::ImmediateTransaction(SqliteConnection& connection) : connection_(connection) {
  connection_.exec("BEGIN IMMEDIATE");
}

ImmediateTransaction::~ImmediateTransaction() {
  if (!open_) return;
  try {
    connection_.exec("ROLLBACK");
  } catch (const StoreError&) {
    // SQLite may already have rolled back (for example after an I/O error); nothing to undo.
  }
}

void ImmediateTransaction::commit() {
  connection_.exec("COMMIT");
  open_ = false;
}

}  // namespace fosls::service
