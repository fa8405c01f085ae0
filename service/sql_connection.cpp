#include "sql_connection.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "job_store.hpp"

namespace fosls::service {

void SqlConnection::fail_disk_full(const std::string& message) const {
  if (disk_observer_) disk_observer_(true, message);
  throw StoreFullError(message);
}

SqlValue sql_optional(const std::optional<std::string>& value) {
  return value ? SqlValue(*value) : SqlValue();
}

const SqlValue& SqlRow::at(std::string_view column) const {
  for (std::size_t i = 0; names_ && i < names_->size() && i < values_.size(); ++i)
    if ((*names_)[i] == column) return values_[i];
  throw StoreError("the result has no column '" + std::string(column) + "'");
}

bool SqlRow::is_null(std::string_view column) const {
  return std::holds_alternative<std::monostate>(at(column));
}

std::int64_t SqlRow::int64(std::string_view column) const {
  const SqlValue& v = at(column);
  if (const auto* i = std::get_if<std::int64_t>(&v)) return *i;
  if (const auto* d = std::get_if<double>(&v)) return static_cast<std::int64_t>(*d);
  if (const auto* s = std::get_if<std::string>(&v)) {
    std::int64_t out = 0;
    std::from_chars(s->data(), s->data() + s->size(), out);
    return out;
  }
  return 0;
}

double SqlRow::real(std::string_view column) const {
  const SqlValue& v = at(column);
  if (const auto* d = std::get_if<double>(&v)) return *d;
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  if (const auto* s = std::get_if<std::string>(&v)) return std::strtod(s->c_str(), nullptr);
  return std::nan("");
}

std::string SqlRow::text(std::string_view column) const {
  const SqlValue& v = at(column);
  if (const auto* s = std::get_if<std::string>(&v)) return *s;
  if (const auto* b = std::get_if<SqlBlob>(&v)) return b->bytes;
  if (const auto* i = std::get_if<std::int64_t>(&v)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&v)) return std::to_string(*d);
  return {};
}

std::optional<std::int64_t> SqlRow::optional_int64(std::string_view column) const {
  if (is_null(column)) return std::nullopt;
  return int64(column);
}

namespace {
void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}
}  // namespace

std::string translate_sql(SqlDialect dialect, const std::string& sql) {
  std::string out = sql;
  if (dialect == SqlDialect::kSqlite) {
    // julianday('now') is fixed for the duration of one statement, as now() is in PostgreSQL.
    replace_all(out, "{now_ms}",
                "CAST(ROUND((julianday('now') - 2440587.5) * 86400000.0) AS INTEGER)");
    replace_all(out, "{skip_locked}", "");
    return out;
  }
  // The database server's clock, so that leases written by hosts with different clocks are
  // compared on one time line.
  replace_all(out, "{now_ms}", "CAST(EXTRACT(EPOCH FROM clock_timestamp()) * 1000 AS BIGINT)");
  replace_all(out, "{skip_locked}", "FOR UPDATE SKIP LOCKED");
  // ?N → $N. The store's SQL has no '?' inside string literals.
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i] == '?' && i + 1 < out.size() &&
        std::isdigit(static_cast<unsigned char>(out[i + 1]))) {
      out[i] = '$';
    }
  }
  return out;
}

}  // namespace fosls::service
