#include "postgres_connection.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "job_store.hpp"

namespace fosls::service {

namespace {

struct ClearResult {
  void operator()(PGresult* r) const { PQclear(r); }
};
using Result = std::unique_ptr<PGresult, ClearResult>;

// Column type OIDs (pg_type.h) that are not read as text.
constexpr Oid kBoolOid = 16;
constexpr Oid kByteaOid = 17;
constexpr Oid kInt8Oid = 20;
constexpr Oid kInt2Oid = 21;
constexpr Oid kInt4Oid = 23;
constexpr Oid kFloat4Oid = 700;
constexpr Oid kFloat8Oid = 701;
constexpr Oid kNumericOid = 1700;

SqlValue column_value(const PGresult* r, int row, int column) {
  if (PQgetisnull(r, row, column)) return {};
  const char* text = PQgetvalue(r, row, column);
  switch (PQftype(r, column)) {
    case kBoolOid:
      return static_cast<std::int64_t>(text[0] == 't');
    case kInt2Oid:
    case kInt4Oid:
    case kInt8Oid:
      return static_cast<std::int64_t>(std::strtoll(text, nullptr, 10));
    case kFloat4Oid:
    case kFloat8Oid:
    case kNumericOid:
      return std::strtod(text, nullptr);  // also reads NaN and Infinity
    case kByteaOid: {
      std::size_t n = 0;
      unsigned char* bytes = PQunescapeBytea(reinterpret_cast<const unsigned char*>(text), &n);
      if (!bytes) throw StoreError("out of memory decoding a bytea column");
      SqlBlob blob{std::string(reinterpret_cast<const char*>(bytes), n)};
      PQfreemem(bytes);
      return blob;
    }
    default:
      return std::string(text, static_cast<std::size_t>(PQgetlength(r, row, column)));
  }
}

}  // namespace

PostgresConnection::PostgresConnection(const std::string& conninfo)
    : conn_(PQconnectdb(conninfo.c_str())) {
  if (!conn_) throw StoreError("out of memory connecting to PostgreSQL");
  if (PQstatus(conn_.get()) != CONNECTION_OK) {
    std::string message = PQerrorMessage(conn_.get());
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
      message.pop_back();
    }
    throw StoreError("cannot connect to PostgreSQL: " + message);
  }
  // NOTICEs (for example "relation already exists, skipping") are not errors: keep them off
  // stderr, which is the service's JSON log.
  PQsetNoticeProcessor(
      conn_.get(), [](void*, const char*) {}, nullptr);
  exec("SET client_min_messages = warning");
}

bool PostgresConnection::usable() const { return PQstatus(conn_.get()) == CONNECTION_OK; }

void PostgresConnection::fail(const std::string& what, const PGresult* result) const {
  std::string message = result ? PQresultErrorMessage(result) : "";
  if (message.empty()) message = PQerrorMessage(conn_.get());
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
    message.pop_back();
  }
  // SQLSTATE 53100: disk_full (the server could not extend a file).
  const char* state = result ? PQresultErrorField(result, PG_DIAG_SQLSTATE) : nullptr;
  if (state && std::string_view(state) == "53100") fail_disk_full(what + ": " + message);
  throw StoreError(what + ": " + message);
}

void PostgresConnection::exec(const std::string& sql) {
  Result r(PQexec(conn_.get(), sql.c_str()));
  const auto status = r ? PQresultStatus(r.get()) : PGRES_FATAL_ERROR;
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) fail(sql, r.get());
  count_written_rows(r.get());
}

void PostgresConnection::count_written_rows(const PGresult* result) {
  // PQcmdTuples also counts the rows a SELECT returned; only writes are changes.
  const std::string_view command = PQcmdStatus(const_cast<PGresult*>(result));
  for (const std::string_view write : {"INSERT", "UPDATE", "DELETE", "MERGE"}) {
    if (command.substr(0, write.size()) == write) {
      rows_changed_ += std::atoll(PQcmdTuples(const_cast<PGresult*>(result)));
      return;
    }
  }
}

void PostgresConnection::rollback() noexcept {
  PGresult* r = PQexec(conn_.get(), "ROLLBACK");
  PQclear(r);
}

const std::string& PostgresConnection::prepared(const std::string& sql, int n_params) {
  auto it = statements_.find(sql);
  if (it != statements_.end()) return it->second;
  const std::string name = "s" + std::to_string(statements_.size() + 1);
  const std::string text = translate_sql(SqlDialect::kPostgres, sql);
  // Parameter types are left to the server (inferred from the columns they meet), except that
  // blobs are sent in binary and must say so.
  Result r(PQprepare(conn_.get(), name.c_str(), text.c_str(), n_params, nullptr));
  if (!r || PQresultStatus(r.get()) != PGRES_COMMAND_OK) fail("preparing '" + text + "'", r.get());
  return statements_.emplace(sql, name).first->second;
}

SqlRows PostgresConnection::query(const std::string& sql, const std::vector<SqlValue>& params) {
  const int n = static_cast<int>(params.size());
  const std::string& name = prepared(sql, n);
  std::vector<std::string> texts(params.size());
  std::vector<const char*> values(params.size(), nullptr);
  std::vector<int> lengths(params.size(), 0);
  std::vector<int> formats(params.size(), 0);
  for (std::size_t i = 0; i < params.size(); ++i) {
    const SqlValue& p = params[i];
    if (const auto* v = std::get_if<std::int64_t>(&p)) {
      texts[i] = std::to_string(*v);
    } else if (const auto* d = std::get_if<double>(&p)) {
      if (!std::isfinite(*d)) continue;  // NULL, as SQLite stores NaN
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g", *d);
      texts[i] = buf;
    } else if (const auto* s = std::get_if<std::string>(&p)) {
      texts[i] = *s;
    } else if (const auto* b = std::get_if<SqlBlob>(&p)) {
      values[i] = b->bytes.data();
      lengths[i] = static_cast<int>(b->bytes.size());
      formats[i] = 1;  // binary: raw bytes, no escaping
      continue;
    } else {
      continue;  // NULL
    }
    values[i] = texts[i].c_str();
    lengths[i] = static_cast<int>(texts[i].size());
  }
  Result r(PQexecPrepared(conn_.get(), name.c_str(), n, values.data(), lengths.data(),
                          formats.data(), 0));
  const auto status = r ? PQresultStatus(r.get()) : PGRES_FATAL_ERROR;
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) {
    fail("running '" + translate_sql(SqlDialect::kPostgres, sql) + "'", r.get());
  }
  count_written_rows(r.get());
  SqlRows rows;
  const int n_rows = PQntuples(r.get());
  const int n_cols = PQnfields(r.get());
  rows.reserve(static_cast<std::size_t>(n_rows));
  auto names = std::make_shared<std::vector<std::string>>();
  for (int c = 0; c < n_cols; ++c) names->emplace_back(PQfname(r.get(), c));
  for (int row = 0; row < n_rows; ++row) {
    std::vector<SqlValue> cells;
    cells.reserve(static_cast<std::size_t>(n_cols));
    for (int c = 0; c < n_cols; ++c) cells.push_back(column_value(r.get(), row, c));
    rows.emplace_back(names, std::move(cells));
  }
  return rows;
}

}  // namespace fosls::service
