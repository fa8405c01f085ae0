#pragma once
// SqlConnection on one libpq connection: statements prepared once per connection, text
// parameters except bytea (binary), results converted by column type. Errors become
// StoreError.

#include <libpq-fe.h>

#include <memory>
#include <string>
#include <unordered_map>

#include "sql_connection.hpp"

namespace fosls::service {

/// One PostgreSQL connection, used by one thread at a time.
class PostgresConnection final : public SqlConnection {
 public:
  /// Connects with a libpq connection string or URL (postgresql://user@host:port/db);
  /// throws StoreError with the server's reason.
  explicit PostgresConnection(const std::string& conninfo);
  PostgresConnection(const PostgresConnection&) = delete;
  PostgresConnection& operator=(const PostgresConnection&) = delete;

  SqlDialect dialect() const override { return SqlDialect::kPostgres; }
  SqlRows query(const std::string& sql, const std::vector<SqlValue>& params = {}) override;
  void exec(const std::string& sql) override;
  void begin_write() override { exec("BEGIN"); }
  void commit() override { exec("COMMIT"); }
  void rollback() noexcept override;
  bool usable() const override;
  std::int64_t rows_changed() const override { return rows_changed_; }

 private:
  struct Finish {
    void operator()(PGconn* c) const { PQfinish(c); }
  };
  /// The name of the prepared statement for store SQL `sql` with `n_params` parameters.
  const std::string& prepared(const std::string& sql, int n_params);
  [[noreturn]] void fail(const std::string& what, const PGresult* result) const;
  /// Adds the rows an INSERT, UPDATE or DELETE wrote to rows_changed_.
  void count_written_rows(const PGresult* result);

  std::unique_ptr<PGconn, Finish> conn_;
  std::unordered_map<std::string, std::string> statements_;  ///< store SQL → statement name
  std::int64_t rows_changed_ = 0;
};

}  // namespace fosls::service
