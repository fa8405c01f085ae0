#include "retention_sweeper.hpp"

namespace fosls::service {

RetentionSweeper::RetentionSweeper(JobStore& store, EventLog& log,
                                   std::chrono::milliseconds retention,
                                   std::chrono::milliseconds interval)
    : store_(store), log_(log), retention_(retention), task_(interval, [this] { sweep_once(); }) {}

int RetentionSweeper::sweep_once() {
  try {
    const int deleted = store_.delete_finished_before(now_unix_ms() - retention_.count());
    if (deleted > 0) log_.write("retention", {{"deleted_jobs", deleted}});
    return deleted;
  } catch (const std::exception& e) {
    log_.write("store_error", {{"step", "retention"}, {"error", e.what()}});
    return 0;
  }
}

}  // namespace fosls::service
