#include "admission_budget.hpp"

namespace fosls::service {

AdmissionBudget::AdmissionBudget(JobStore& store, std::size_t own_bytes,
                                 std::chrono::milliseconds refresh)
    : store_(store), own_bytes_(own_bytes), refresh_(refresh) {}

MemoryBudget AdmissionBudget::current() {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (!read_at_ || now - *read_at_ >= refresh_) {
    try {
      if (auto declared = store_.declared_worker_budget()) declared_ = declared;
    } catch (const StoreError&) {
      // keep the last budget read; the submission itself will meet the store's trouble
    }
    read_at_ = now;
  }
  if (declared_)
    return {*declared_, "a job may use (the workers' --max-job-memory, as they declared it)"};
  return {own_bytes_, "a job may use (the service's --max-job-memory)"};
}

}  // namespace fosls::service
