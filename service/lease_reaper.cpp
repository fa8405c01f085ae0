#include "lease_reaper.hpp"

namespace fosls::service {

void log_recovery(EventLog& log, const RecoveryReport& report, const std::string& reason) {
  for (auto id : report.requeued) {
    log.write("job_transition",
              {{"job_id", id}, {"from", "running"}, {"to", "queued"}, {"reason", reason}});
  }
  for (auto id : report.failed) {
    log.write("job_transition", {{"job_id", id},
                                 {"from", "running"},
                                 {"to", "failed"},
                                 {"reason", reason + "; max attempts reached"}});
  }
  for (auto id : report.cancelled) {
    log.write("job_transition",
              {{"job_id", id}, {"from", "running"}, {"to", "cancelled"}, {"reason", reason}});
  }
}

LeaseReaper::LeaseReaper(JobStore& store, EventLog& log, int max_attempts,
                         std::chrono::milliseconds interval)
    : store_(store),
      log_(log),
      max_attempts_(max_attempts),
      task_(interval, [this] { reap_once(); }) {}

RecoveryReport LeaseReaper::reap_once() {
  try {
    RecoveryReport report = store_.requeue_expired_leases(max_attempts_);
    log_recovery(log_, report, "lease expired");
    return report;
  } catch (const std::exception& e) {
    log_.write("store_error", {{"step", "lease expiry"}, {"error", e.what()}});
    return {};
  }
}

}  // namespace fosls::service
