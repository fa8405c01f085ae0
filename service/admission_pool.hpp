#pragma once
// Heavy request work off the HTTP threads: reading a large submission (JSON parse, duplicate
// keys, admission of a 4 MiB case takes a good part of a second of CPU) runs on a few threads
// of low CPU priority while the request's own thread waits, so that requests that need little
// (GET /healthz, job polls) are not queued behind that CPU (docs/service.md, "Hostile use").
// The memory the work allocated goes back to the system after each piece.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fosls::service {

class AdmissionPool {
 public:
  /// `threads` workers at nice +10; at most `max_waiting` calls queue for them.
  AdmissionPool(int threads, std::size_t max_waiting);
  ~AdmissionPool();
  AdmissionPool(const AdmissionPool&) = delete;
  AdmissionPool& operator=(const AdmissionPool&) = delete;

  /// Runs `work` on a pool thread and returns when it is done; false, without running it, when
  /// `max_waiting` calls are queued already (the caller answers 503). Exceptions of `work`
  /// are rethrown here.
  bool run(const std::function<void()>& work);

 private:
  struct Task;
  void serve();

  std::size_t max_waiting_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Task*> queue_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace fosls::service
