#pragma once
// --store URL of the programs: which job store, and opening it for one process.
//
//   sqlite:data/fosls.db                        one fosls-serve, a file on its disk
//   postgresql://user:pass@db-host:5432/fosls   any number of fosls-serve and fosls-worker

#include <memory>
#include <string>

#include "job_store.hpp"

namespace fosls::service {

/// A parsed --store value.
struct StoreLocation {
  enum class Kind { kSqlite, kPostgres };
  Kind kind = Kind::kSqlite;
  std::string target;  ///< the SQLite path, or the libpq URL as given
};

/// Parses "sqlite:PATH", "postgresql://…" or "postgres://…"; throws std::invalid_argument
/// saying what is accepted.
StoreLocation parse_store_url(const std::string& url);

/// The location for logs: a password in a PostgreSQL URL is replaced by "***".
std::string redacted(const StoreLocation& location);

/// A store opened by a program, with what start-up did.
struct OpenedStore {
  std::unique_ptr<JobStore> store;
  StoreLocation location;
  RecoveryReport recovered;  ///< jobs moved at start
  std::string recovery_reason;
  /// The SQLite owner lock (kernel-held until exit, also on kill -9); -1 for PostgreSQL.
  int lock_fd = -1;

  OpenedStore() = default;
  OpenedStore(OpenedStore&& other) noexcept;
  OpenedStore& operator=(OpenedStore&& other) noexcept;
  ~OpenedStore();
};

/// Opens the store for `program`. A SQLite file belongs to one process: it is locked (a second
/// program on it is refused) and every job left running is recovered at once. A PostgreSQL
/// database is shared: only jobs whose lease expired are recovered (LeaseReaper keeps doing
/// that). Throws std::runtime_error (StoreError for the database) with a message for a person.
OpenedStore open_store(const StoreLocation& location, const std::string& program, int max_attempts);

}  // namespace fosls::service
