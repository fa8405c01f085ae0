#pragma once
// Lease expiry, run by every process on a shared store (API and worker processes alike):
// whoever notices first puts the jobs of a dead worker back in the queue.

#include <chrono>
#include <string>

#include "event_log.hpp"
#include "job_store.hpp"
#include "periodic_task.hpp"

namespace fosls::service {

/// Logs one job_transition line per job that recovery moved, with `reason`.
void log_recovery(EventLog& log, const RecoveryReport& report, const std::string& reason);

/// A background thread calling JobStore::requeue_expired_leases every `interval`.
class LeaseReaper {
 public:
  /// `store` and `log` must outlive the reaper.
  LeaseReaper(JobStore& store, EventLog& log, int max_attempts, std::chrono::milliseconds interval);

  void start() { task_.start(); }
  void stop() { task_.stop(); }

  /// One pass now.
  RecoveryReport reap_once();

 private:
  JobStore& store_;
  EventLog& log_;
  int max_attempts_;
  PeriodicTask task_;  ///< last: stopped before the members it uses are destroyed
};

}  // namespace fosls::service
