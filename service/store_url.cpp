#include "store_url.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "postgres_job_store.hpp"
#include "sqlite_job_store.hpp"

namespace fosls::service {

StoreLocation parse_store_url(const std::string& url) {
  StoreLocation location;
  if (url.rfind("sqlite:", 0) == 0) {
    location.kind = StoreLocation::Kind::kSqlite;
    location.target = url.substr(7);
    if (location.target.rfind("//", 0) == 0) location.target = location.target.substr(2);
    if (location.target.empty()) {
      throw std::invalid_argument("--store sqlite: needs a file path, e.g. sqlite:data/fosls.db");
    }
    return location;
  }
  if (url.rfind("postgresql://", 0) == 0 || url.rfind("postgres://", 0) == 0) {
    location.kind = StoreLocation::Kind::kPostgres;
    location.target = url;
    return location;
  }
  throw std::invalid_argument("--store '" + url +
                              "' is not a store URL: use sqlite:PATH (one process) or "
                              "postgresql://USER:PASSWORD@HOST:PORT/DATABASE (shared)");
}

std::string redacted(const StoreLocation& location) {
  if (location.kind == StoreLocation::Kind::kSqlite) return "sqlite:" + location.target;
  std::string url = location.target;
  const auto scheme = url.find("://");
  const auto at = url.find('@', scheme + 3);
  if (at == std::string::npos) return url;
  const auto colon = url.find(':', scheme + 3);
  if (colon != std::string::npos && colon < at) url.replace(colon + 1, at - colon - 1, "***");
  return url;
}

OpenedStore::OpenedStore(OpenedStore&& other) noexcept
    : store(std::move(other.store)),
      location(std::move(other.location)),
      recovered(std::move(other.recovered)),
      recovery_reason(std::move(other.recovery_reason)),
      lock_fd(other.lock_fd) {
  other.lock_fd = -1;
}

OpenedStore& OpenedStore::operator=(OpenedStore&& other) noexcept {
  std::swap(store, other.store);
  std::swap(location, other.location);
  std::swap(recovered, other.recovered);
  std::swap(recovery_reason, other.recovery_reason);
  std::swap(lock_fd, other.lock_fd);
  return *this;
}

OpenedStore::~OpenedStore() {
  if (lock_fd >= 0) close(lock_fd);
}

OpenedStore open_store(const StoreLocation& location, const std::string& program,
                       int max_attempts) {
  OpenedStore opened;
  opened.location = location;
  if (location.kind == StoreLocation::Kind::kPostgres) {
    opened.store = std::make_unique<PostgresJobStore>(location.target);
    opened.recovered = opened.store->requeue_expired_leases(max_attempts);
    opened.recovery_reason = "lease expired";
    return opened;
  }
  const std::filesystem::path path(location.target);
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  // Start-up recovery assumes this process owns every running job of the file; a second
  // program on it would re-queue the first one's jobs. The kernel drops the lock when the
  // process dies, also on kill -9.
  const std::string lock_path = location.target + ".lock";
  opened.lock_fd = open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  // A child that the previous process forked holds the lock until it calls exec (the
  // descriptor is close-on-exec): after a kill -9 that is a few milliseconds, so wait up to 2 s
  // before calling the store taken (seen as a flaky restart in the kill -9 test under load).
  bool locked = false;
  for (int attempt = 0; opened.lock_fd >= 0 && attempt < 20 && !locked; ++attempt) {
    locked = flock(opened.lock_fd, LOCK_EX | LOCK_NB) == 0;
    if (!locked) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (!locked) {
    throw std::runtime_error("another fosls-serve is using " + location.target + " (lock " +
                             lock_path + "); a SQLite store belongs to one process, " + program +
                             " processes that share a queue need --store postgresql://…");
  }
  opened.store = std::make_unique<SqliteJobStore>(location.target);
  opened.recovered = opened.store->recover_interrupted(max_attempts);
  opened.recovery_reason = "recovered after the previous process stopped";
  return opened;
}

}  // namespace fosls::service
