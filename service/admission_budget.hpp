#pragma once
// The memory budget an API process admits cases against (docs/service.md, "Command line",
// --max-job-memory): the workers' --max-job-memory as they declared it in the store — the smallest
// of those running, since any of them may claim any job — else, before any worker declared one,
// this process's own --max-job-memory. An API-only process (--workers 0) therefore refuses what its
// workers could not run, whatever memory its own host has.

#include <chrono>
#include <cstddef>
#include <mutex>
#include <optional>
#include <string>

#include "job_store.hpp"

namespace fosls::service {

/// A budget and what completes "more than the 2 GiB …" in messages (who set it).
struct MemoryBudget {
  std::size_t bytes = 0;
  std::string name;
};

class AdmissionBudget {
 public:
  /// `own_bytes`: this process's --max-job-memory (or its default).
  AdmissionBudget(JobStore& store, std::size_t own_bytes,
                  std::chrono::milliseconds refresh = std::chrono::seconds(2));

  /// The budget now; the store is read at most every `refresh` (a request thread calls this on
  /// every submission), and a store that fails keeps the last budget read.
  MemoryBudget current();

 private:
  JobStore& store_;
  std::size_t own_bytes_;
  std::chrono::milliseconds refresh_;
  std::mutex mutex_;
  std::optional<std::chrono::steady_clock::time_point> read_at_;
  std::optional<std::size_t> declared_;
};

}  // namespace fosls::service
