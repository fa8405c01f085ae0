#pragma once
// The HTTP server's threads: a fixed core that grows, up to a cap, whenever every thread is
// busy. A connection holds its thread until its request is read, so a few slow or silent
// clients would otherwise keep everyone else (and /healthz) waiting for their read timeout.

#include <httplib.h>

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fosls::service {

class ElasticThreadPool : public httplib::TaskQueue {
 public:
  /// `core` threads at once, more (up to `max_threads`) while all are busy; they stay.
  ElasticThreadPool(int core, int max_threads);
  ~ElasticThreadPool() override;

  void enqueue(std::function<void()> fn) override;
  void shutdown() override;

  int threads() const;

 private:
  void add_thread();  // mutex_ held
  void run();

  const int max_threads_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  std::vector<std::thread> threads_;
  int idle_ = 0;
  bool stopping_ = false;
};

}  // namespace fosls::service
