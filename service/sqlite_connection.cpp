#include "sqlite_connection.hpp"

#include <algorithm>
#include <cmath>
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
  // Before WAL: auto_vacuum takes effect only while the file has no tables, and switching to
  // WAL already writes the header. Existing files are converted by the schema migration.
  exec("PRAGMA auto_vacuum=INCREMENTAL");
  exec("PRAGMA journal_mode=WAL");
  exec("PRAGMA synchronous=FULL");
  exec("PRAGMA foreign_keys=ON");
  // A large result grows the WAL file; a checkpoint truncates it back to this size.
  exec("PRAGMA journal_size_limit=67108864");
}

void SqliteConnection::exec(const std::string& sql) {
  char* message = nullptr;
  const int rc = sqlite3_exec(db_.get(), sql.c_str(), nullptr, nullptr, &message);
  if (rc != SQLITE_OK) {
    std::string text = message ? message : sqlite3_errstr(rc);
    sqlite3_free(message);
    if ((rc & 0xff) == SQLITE_FULL) fail_disk_full(sql + ": " + text);
    throw StoreError(sql + ": " + text);
  }
}

namespace {

using BlobHandle = std::unique_ptr<sqlite3_blob, int (*)(sqlite3_blob*)>;

/// The blob handle of a value (its own short read transaction), nothing when the row is gone.
std::optional<BlobHandle> open_blob(SqliteConnection& c, sqlite3* db, const char* table,
                                    const char* column, std::int64_t rowid) {
  sqlite3_blob* raw = nullptr;
  const int rc = sqlite3_blob_open(db, "main", table, column, rowid, 0, &raw);
  BlobHandle blob(raw, sqlite3_blob_close);
  if (rc == SQLITE_OK) return blob;
  const std::string message = sqlite3_errmsg(db);
  // A row deleted meanwhile is an answer, not an error.
  if (c.query(std::string("SELECT 1 AS found FROM ") + table + " WHERE rowid = ?1", {rowid})
          .empty())
    return std::nullopt;
  throw StoreError(std::string("reading ") + table + "." + column + ": " + message +
                   " (SQLite code " + std::to_string(rc) + ")");
}

}  // namespace

std::optional<std::string> SqliteConnection::read_blob(const char* table, const char* column,
                                                       std::int64_t rowid, std::int64_t offset,
                                                       std::int64_t length) {
  const auto blob = open_blob(*this, db_.get(), table, column, rowid);
  if (!blob) return std::nullopt;
  const std::int64_t size = sqlite3_blob_bytes(blob->get());
  const std::int64_t from = std::clamp<std::int64_t>(offset, 0, size);
  std::string part(static_cast<std::size_t>(std::clamp<std::int64_t>(length, 0, size - from)),
                   '\0');
  if (!part.empty()) {
    const int read = sqlite3_blob_read(blob->get(), part.data(), static_cast<int>(part.size()),
                                       static_cast<int>(from));
    if (read != SQLITE_OK) fail(read, std::string("reading ") + table + "." + column);
  }
  // The part's pages stay in this connection's page cache (2 MB at most; each HTTP thread has
  // a connection): give them back, since the next part of a stalled client may be seconds away.
  sqlite3_db_release_memory(db_.get());
  return part;
}

std::optional<std::int64_t> SqliteConnection::blob_size(const char* table, const char* column,
                                                        std::int64_t rowid) {
  const auto blob = open_blob(*this, db_.get(), table, column, rowid);
  if (!blob) return std::nullopt;
  return sqlite3_blob_bytes(blob->get());
}

void SqliteConnection::rollback() noexcept {
  // SQLite may already have rolled back (for example after an I/O error); nothing to undo.
  sqlite3_exec(db_.get(), "ROLLBACK", nullptr, nullptr, nullptr);
}

sqlite3_stmt& SqliteConnection::statement(const std::string& sql) {
  auto it = statements_.find(sql);
  if (it != statements_.end()) return *it->second;
  const std::string text = translate_sql(SqlDialect::kSqlite, sql);
  sqlite3_stmt* raw = nullptr;
  const int rc = sqlite3_prepare_v3(db_.get(), text.c_str(), static_cast<int>(text.size()),
                                    SQLITE_PREPARE_PERSISTENT, &raw, nullptr);
  std::unique_ptr<sqlite3_stmt, FinalizeStmt> stmt(raw);
  if (rc != SQLITE_OK) fail(rc, "preparing '" + text + "'");
  sqlite3_stmt& ref = *stmt;
  statements_.emplace(sql, std::move(stmt));
  return ref;
}

void SqliteConnection::bind(sqlite3_stmt& stmt, int index, const SqlValue& value) {
  int rc = SQLITE_OK;
  if (const auto* i = std::get_if<std::int64_t>(&value)) {
    rc = sqlite3_bind_int64(&stmt, index, *i);
  } else if (const auto* d = std::get_if<double>(&value)) {
    // SQLite would store NaN as NULL anyway; infinities likewise, so both stores agree.
    rc =
        std::isfinite(*d) ? sqlite3_bind_double(&stmt, index, *d) : sqlite3_bind_null(&stmt, index);
  } else if (const auto* s = std::get_if<std::string>(&value)) {
    rc = sqlite3_bind_text64(&stmt, index, s->data(), s->size(), SQLITE_TRANSIENT, SQLITE_UTF8);
  } else if (const auto* b = std::get_if<SqlBlob>(&value)) {
    rc = sqlite3_bind_blob64(&stmt, index, b->bytes.data(), b->bytes.size(), SQLITE_TRANSIENT);
  } else {
    rc = sqlite3_bind_null(&stmt, index);
  }
  if (rc != SQLITE_OK) fail(rc, "binding parameter " + std::to_string(index));
}

SqlRows SqliteConnection::query(const std::string& sql, const std::vector<SqlValue>& params) {
  sqlite3_stmt& stmt = statement(sql);
  // Reset even when a step throws, so the connection holds no open read.
  struct Reset {
    sqlite3_stmt& s;
    ~Reset() {
      sqlite3_reset(&s);
      sqlite3_clear_bindings(&s);
    }
  } reset{stmt};
  for (std::size_t i = 0; i < params.size(); ++i) bind(stmt, static_cast<int>(i + 1), params[i]);
  SqlRows rows;
  SqlColumnNames names;
  for (;;) {
    const int rc = sqlite3_step(&stmt);
    if (rc == SQLITE_DONE) break;
    if (rc != SQLITE_ROW) fail(rc, std::string("running '") + sqlite3_sql(&stmt) + "'");
    const int columns = sqlite3_column_count(&stmt);
    if (!names) {
      auto list = std::make_shared<std::vector<std::string>>();
      for (int c = 0; c < columns; ++c) list->emplace_back(sqlite3_column_name(&stmt, c));
      names = std::move(list);
    }
    std::vector<SqlValue> values(static_cast<std::size_t>(columns));
    for (int c = 0; c < columns; ++c) {
      auto& v = values[static_cast<std::size_t>(c)];
      switch (sqlite3_column_type(&stmt, c)) {
        case SQLITE_INTEGER:
          v = static_cast<std::int64_t>(sqlite3_column_int64(&stmt, c));
          break;
        case SQLITE_FLOAT:
          v = sqlite3_column_double(&stmt, c);
          break;
        case SQLITE_TEXT:
          v = std::string(reinterpret_cast<const char*>(sqlite3_column_text(&stmt, c)),
                          static_cast<std::size_t>(sqlite3_column_bytes(&stmt, c)));
          break;
        case SQLITE_BLOB: {
          const auto* data = static_cast<const char*>(sqlite3_column_blob(&stmt, c));
          v = SqlBlob{std::string(data ? data : "",
                                  static_cast<std::size_t>(sqlite3_column_bytes(&stmt, c)))};
          break;
        }
        default:
          break;  // NULL
      }
    }
    rows.emplace_back(names, std::move(values));
  }
  return rows;
}

void SqliteConnection::fail(int code, std::string_view what) const {
  std::string message = std::string(what) + ": ";
  message += db_ ? sqlite3_errmsg(db_.get()) : sqlite3_errstr(code);
  message += " (SQLite code " + std::to_string(code) + ")";
  if ((code & 0xff) == SQLITE_FULL) fail_disk_full(message);
  throw StoreError(message);
}

}  // namespace fosls::service
