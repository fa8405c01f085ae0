#pragma once
// A job store whose disk is full, for the HTTP layer's tests where no small disk can be
// mounted: every write throws StoreFullError with SQLite's message and health says so; reads
// go to a real store underneath.

#include "forwarding_store.hpp"

namespace fosls::service::testing {

class DiskFullStore : public ForwardingStore {
 public:
  using ForwardingStore::ForwardingStore;

  SubmitOutcome submit(const NewJob&, std::size_t) override { full(); }
  CancelOutcome cancel(std::int64_t) override { full(); }
  DeleteOutcome remove(std::int64_t) override { full(); }
  std::optional<ClaimedJob> claim_next(const ClaimRequest&) override { full(); }
  LeaseStatus renew_lease(const Lease&, std::chrono::milliseconds) override { full(); }
  void update_progress(const Lease&, const JobProgress&) override { full(); }
  bool complete_with_result(const Lease&, const SolveRecord&) override { full(); }
  bool complete_failed(const Lease&, const std::string&) override { full(); }
  bool complete_cancelled(const Lease&) override { full(); }
  bool requeue(const Lease&) override { full(); }
  void declare_worker_budget(const std::string&, std::size_t) override { full(); }
  StoreHealth health() override { return {true, kMessage}; }

  static constexpr const char* kMessage =
      "running 'INSERT INTO jobs ...': database or disk is full (SQLite code 13)";

 private:
  [[noreturn]] static void full() { throw StoreFullError(kMessage); }
};

}  // namespace fosls::service::testing
