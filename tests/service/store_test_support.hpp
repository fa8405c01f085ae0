#pragma once
// What the store tests share: jobs to submit, claim requests, and the two stores to run the one
// contract against (a SQLite file, or a database on a throwaway PostgreSQL server).

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "postgres_cluster.hpp"
#include "postgres_connection.hpp"
#include "postgres_job_store.hpp"
#include "request_checks.hpp"
#include "sqlite_connection.hpp"
#include "sqlite_job_store.hpp"
#include "temp_dir.hpp"

namespace fosls::service::testing {

inline NewJob make_job(const std::string& body, std::optional<std::string> key = std::nullopt) {
  NewJob job;
  job.name = "case";
  job.case_json = body;
  job.body_hash = sha256_hex(body);
  job.idempotency_key = std::move(key);
  return job;
}

constexpr std::size_t kUnlimited = 1'000'000;

/// A claim by `worker` with a lease long enough never to expire during a test.
inline ClaimRequest claim_as(const std::string& worker = "w1",
                             std::chrono::milliseconds lease = std::chrono::minutes(10)) {
  return ClaimRequest{worker, lease};
}

/// The PostgreSQL server of this test process, started on first use and stopped at exit.
inline PostgresCluster& shared_postgres() {
  static PostgresCluster cluster;
  return cluster;
}

/// A database for one test: a SQLite file in a temporary folder, or a new database on the
/// shared PostgreSQL server. open() may be called again for a second store object on the same
/// data (another process, or the same one after a restart).
class StoreUnderTest {
 public:
  explicit StoreUnderTest(const std::string& kind) : kind_(kind) {
    if (kind_ == "postgresql") {
      static std::atomic<int> counter{0};
      url_ = shared_postgres().create_database("contract_" + std::to_string(getpid()) + "_" +
                                               std::to_string(++counter));
    }
  }

  std::unique_ptr<JobStore> open() const {
    if (kind_ == "postgresql") return std::make_unique<PostgresJobStore>(url_);
    return std::make_unique<SqliteJobStore>(dir_.file("jobs.db"));
  }

  /// A plain connection to the same data, for SQL a test writes itself (an older schema).
  std::unique_ptr<SqlConnection> connect() const {
    if (kind_ == "postgresql") return std::make_unique<PostgresConnection>(url_);
    return std::make_unique<SqliteConnection>(dir_.file("jobs.db"), 5000);
  }

  const std::string& kind() const { return kind_; }
  /// The --store URL the programs take.
  std::string store_url() const {
    return kind_ == "postgresql" ? url_ : "sqlite:" + dir_.file("jobs.db");
  }

 private:
  std::string kind_;
  TempDir dir_;
  std::string url_;
};

}  // namespace fosls::service::testing
