#pragma once
// A job store whose disk is full, for the HTTP layer's tests where no small disk can be
// mounted: every write throws StoreFullError with SQLite's message and health says so; reads
// go to a real store underneath.

#include "job_store.hpp"

namespace fosls::service::testing {

class DiskFullStore : public JobStore {
 public:
  explicit DiskFullStore(JobStore& reads) : reads_(reads) {}

  SubmitOutcome submit(const NewJob&, std::size_t) override { full(); }
  std::optional<Job> find(std::int64_t id) override { return reads_.find(id); }
  std::optional<std::string> result_json(std::int64_t id) override {
    return reads_.result_json(id);
  }
  std::optional<std::string> vtu(std::int64_t id) override { return reads_.vtu(id); }
  std::optional<std::string> case_json(std::int64_t id) override { return reads_.case_json(id); }
  JobPage list(const JobListQuery& query) override { return reads_.list(query); }
  CancelOutcome cancel(std::int64_t) override { full(); }
  DeleteOutcome remove(std::int64_t) override { full(); }
  std::optional<ClaimedJob> claim_next(const ClaimRequest&) override { full(); }
  LeaseStatus renew_lease(const Lease&, std::chrono::milliseconds) override { full(); }
  void update_progress(const Lease&, const JobProgress&) override { full(); }
  bool complete_with_result(const Lease&, const SolveRecord&) override { full(); }
  bool complete_failed(const Lease&, const std::string&) override { full(); }
  bool complete_cancelled(const Lease&) override { full(); }
  bool requeue(const Lease&) override { full(); }
  RecoveryReport requeue_expired_leases(int) override { full(); }
  RecoveryReport recover_interrupted(int) override { full(); }
  int delete_finished_before(std::int64_t) override { full(); }
  std::map<JobState, std::int64_t> count_by_state() override { return reads_.count_by_state(); }
  std::int64_t count_not_converged() override { return reads_.count_not_converged(); }
  void ping() override { reads_.ping(); }
  StoreHealth health() override { return {true, kMessage}; }

  static constexpr const char* kMessage =
      "running 'INSERT INTO jobs ...': database or disk is full (SQLite code 13)";

 private:
  [[noreturn]] static void full() { throw StoreFullError(kMessage); }
  JobStore& reads_;
};

}  // namespace fosls::service::testing
