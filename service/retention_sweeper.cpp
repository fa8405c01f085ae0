#include "retention_sweeper.hpp"

namespace fosls::service {

RetentionSweeper::RetentionSweeper(JobStore& store, EventLog& log,
                                   std::chrono::milliseconds retention,
                                   std::chrono::milliseconds interval)
    : store_(store), log_(log), retention_(retention), interval_(interval) {}

RetentionSweeper::~RetentionSweeper() { stop(); }

void RetentionSweeper::start() {
  if (thread_.joinable()) return;
  thread_ = std::thread([this] {
    std::unique_lock lock(mutex_);
    while (!stopping_) {
      lock.unlock();
      sweep_once();
      lock.lock();
      wake_.wait_for(lock, interval_, [this] { return stopping_; });
    }
  });
}

void RetentionSweeper::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

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
