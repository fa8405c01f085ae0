#pragma once
// A JobStore that hands every call to another store: test doubles derive from it and change
// only the calls they are about (counting progress writes, a full disk, ...).

#include "job_store.hpp"

namespace fosls::service::testing {

class ForwardingStore : public JobStore {
 public:
  explicit ForwardingStore(JobStore& inner) : inner_(inner) {}

  SubmitOutcome submit(const NewJob& j, std::size_t m) override { return inner_.submit(j, m); }
  std::optional<Job> find(std::int64_t id) override { return inner_.find(id); }
  std::optional<std::string> result_json(std::int64_t id) override {
    return inner_.result_json(id);
  }
  std::optional<std::int64_t> result_json_size(std::int64_t id) override {
    return inner_.result_json_size(id);
  }
  std::optional<std::string> result_json_bytes(std::int64_t id, std::int64_t offset,
                                               std::int64_t length) override {
    return inner_.result_json_bytes(id, offset, length);
  }
  std::optional<std::string> vtu(std::int64_t id) override { return inner_.vtu(id); }
  std::optional<StoredVtu> stored_vtu(std::int64_t id) override { return inner_.stored_vtu(id); }
  std::optional<std::string> stored_vtu_bytes(std::int64_t id, std::int64_t offset,
                                              std::int64_t length) override {
    return inner_.stored_vtu_bytes(id, offset, length);
  }
  std::optional<std::string> case_json(std::int64_t id) override { return inner_.case_json(id); }
  JobPage list(const JobListQuery& q) override { return inner_.list(q); }
  CancelOutcome cancel(std::int64_t id) override { return inner_.cancel(id); }
  DeleteOutcome remove(std::int64_t id) override { return inner_.remove(id); }
  std::optional<ClaimedJob> claim_next(const ClaimRequest& r) override {
    return inner_.claim_next(r);
  }
  LeaseStatus renew_lease(const Lease& l, std::chrono::milliseconds d) override {
    return inner_.renew_lease(l, d);
  }
  void update_progress(const Lease& l, const JobProgress& p) override {
    inner_.update_progress(l, p);
  }
  bool complete_with_result(const Lease& l, const SolveRecord& r) override {
    return inner_.complete_with_result(l, r);
  }
  bool complete_failed(const Lease& l, const std::string& e) override {
    return inner_.complete_failed(l, e);
  }
  bool complete_cancelled(const Lease& l) override { return inner_.complete_cancelled(l); }
  bool requeue(const Lease& l) override { return inner_.requeue(l); }
  RecoveryReport requeue_expired_leases(int m) override { return inner_.requeue_expired_leases(m); }
  RecoveryReport recover_interrupted(int m) override { return inner_.recover_interrupted(m); }
  int delete_finished_before(std::int64_t t) override { return inner_.delete_finished_before(t); }
  std::map<JobState, std::int64_t> count_by_state() override { return inner_.count_by_state(); }
  std::int64_t count_not_converged() override { return inner_.count_not_converged(); }
  void ping() override { inner_.ping(); }
  StoreHealth health() override { return inner_.health(); }
  void declare_worker_budget(const std::string& id, std::size_t bytes) override {
    inner_.declare_worker_budget(id, bytes);
  }
  std::optional<std::size_t> declared_worker_budget() override {
    return inner_.declared_worker_budget();
  }

 private:
  JobStore& inner_;
};

}  // namespace fosls::service::testing
