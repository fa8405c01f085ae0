#pragma once
// Periodic deletion of finished jobs older than the retention period (--retention-hours).

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "event_log.hpp"
#include "job_store.hpp"

namespace fosls::service {

/// A background thread that deletes finished jobs (with results) once they are older than
/// `retention`, checking every `interval`.
class RetentionSweeper {
 public:
  /// `store` and `log` must outlive the sweeper.
  RetentionSweeper(JobStore& store, EventLog& log, std::chrono::milliseconds retention,
                   std::chrono::milliseconds interval);
  ~RetentionSweeper();
  RetentionSweeper(const RetentionSweeper&) = delete;
  RetentionSweeper& operator=(const RetentionSweeper&) = delete;

  void start();
  void stop();

  /// One pass now; returns how many jobs were deleted.
  int sweep_once();

 private:
  JobStore& store_;
  EventLog& log_;
  std::chrono::milliseconds retention_;
  std::chrono::milliseconds interval_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace fosls::service
