#include "admission_pool.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <exception>

#include "process/malloc_arenas.hpp"

namespace fosls::service {

struct AdmissionPool::Task {
  const std::function<void()>* work;
  std::exception_ptr error;
  bool done = false;
};

AdmissionPool::AdmissionPool(int threads, std::size_t max_waiting) : max_waiting_(max_waiting) {
  for (int i = 0; i < std::max(1, threads); ++i) threads_.emplace_back([this] { serve(); });
}

AdmissionPool::~AdmissionPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& t : threads_) t.join();
}

bool AdmissionPool::run(const std::function<void()>& work) {
  Task task{&work};
  std::unique_lock lock(mutex_);
  if (queue_.size() >= max_waiting_ || stopping_) return false;
  queue_.push_back(&task);
  wake_.notify_all();
  wake_.wait(lock, [&] { return task.done; });
  if (task.error) std::rethrow_exception(task.error);
  return true;
}

void AdmissionPool::serve() {
  // Linux gives each thread its own nice value; a lower priority than the HTTP threads'
  // lets /healthz and polls preempt this work (an unprivileged thread cannot raise it again,
  // which is why the work moves here instead of lowering the request's own thread).
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 10);
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, nothing left
    Task* task = queue_.front();
    queue_.pop_front();
    lock.unlock();
    try {
      (*task->work)();
    } catch (...) {
      task->error = std::current_exception();
    }
    return_freed_memory();  // the parsed case's many small blocks
    lock.lock();
    task->done = true;
    wake_.notify_all();
  }
}

}  // namespace fosls::service
