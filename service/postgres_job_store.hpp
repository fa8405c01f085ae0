#pragma once
// JobStore on PostgreSQL, shared by any number of API and worker processes on any hosts:
// claims skip rows other claimers hold (FOR UPDATE SKIP LOCKED), leases are timed by the
// database's clock, and results and VTU live in the database so any API process serves any
// job (docs/service.md, "Several hosts").

#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "postgres_connection.hpp"
#include "sql_job_store.hpp"

namespace fosls::service {

/// PostgreSQL job store with a bounded pool of connections (calls beyond the bound wait for
/// one). A broken connection (the server restarted) is dropped and replaced on next use.
class PostgresJobStore final : public SqlJobStore {
 public:
  /// Connects with a libpq URL or connection string and brings the schema to the current
  /// version (several processes may start at once). Throws StoreError.
  explicit PostgresJobStore(std::string conninfo, int max_connections = 8);
  /// In bytes of the text as UTF-8 (the column is text, whose substr counts characters).
  std::optional<std::int64_t> result_json_size(std::int64_t id) override;
  std::optional<std::string> result_json_bytes(std::int64_t id, std::int64_t offset,
                                               std::int64_t length) override;

 protected:
  void serialize_submits(SqlConnection& c) override;

 private:
  SqlConnectionHandle borrow();
  void give_back(SqlConnection* c);
  void migrate();

  std::string conninfo_;
  int max_connections_;
  std::mutex mutex_;
  std::condition_variable returned_;
  int open_ = 0;  ///< connections in existence (idle and lent)
  std::vector<std::unique_ptr<SqlConnection>> idle_;
};

}  // namespace fosls::service
