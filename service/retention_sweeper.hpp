#pragma once
// Periodic deletion of finished jobs older than the retention period (--retention-hours).

#include <chrono>

#include "event_log.hpp"
#include "job_store.hpp"
#include "periodic_task.hpp"

namespace fosls::service {

/// A background thread that deletes finished jobs (with results) once they are older than
/// `retention`, checking every `interval`.
class RetentionSweeper {
 public:
  /// `store` and `log` must outlive the sweeper.
  RetentionSweeper(JobStore& store, EventLog& log, std::chrono::milliseconds retention,
                   std::chrono::milliseconds interval);

  void start() { task_.start(); }
  void stop() { task_.stop(); }

  /// One pass now; returns how many jobs were deleted.
  int sweep_once();

 private:
  JobStore& store_;
  EventLog& log_;
  std::chrono::milliseconds retention_;
  PeriodicTask task_;  ///< last: stopped before the members it uses are destroyed
};

}  // namespace fosls::service
