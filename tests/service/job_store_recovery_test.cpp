// The job-store contract, continued (job_store_contract.hpp; instantiated for both stores in
// job_store_contract_test.cpp): recovery after a crash, leases (renewal, expiry, the late worker
// refused), retention, and claim exclusivity with many threads on several store objects at once
// (as several processes).

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "job_store_contract.hpp"

// In the support's namespace: the fixture, claim_as, make_job and kUnlimited without usings.
namespace fosls::service::testing {
namespace {

using namespace std::chrono_literals;

TEST_P(JobStoreContract, RecoveryRequeuesThenFailsAtMaxAttemptsAndHonoursCancels) {
  const auto a = submit("1");
  const auto b = submit("2");
  const auto c = submit("3");
  ASSERT_EQ(store().claim_next(claim_as())->job.id, a);
  ASSERT_EQ(store().claim_next(claim_as())->job.id, b);
  ASSERT_EQ(store().cancel(b).kind, CancelOutcome::Kind::kRequested);
  // The process "crashes" here: the store goes away with a and b running.
  store_ = db_->open();
  RecoveryReport report = store().recover_interrupted(2);
  EXPECT_EQ(report.requeued, std::vector<std::int64_t>{a});
  EXPECT_EQ(report.cancelled, std::vector<std::int64_t>{b});
  EXPECT_TRUE(report.failed.empty());
  EXPECT_EQ(store().find(b)->state, JobState::kCancelled);
  EXPECT_EQ(store().find(c)->state, JobState::kQueued);
  auto again = store().claim_next(claim_as());
  ASSERT_EQ(again->job.id, a);
  EXPECT_EQ(again->job.attempts, 2);
  // ... and crashes again while solving a.
  store_ = db_->open();
  report = store().recover_interrupted(2);
  EXPECT_EQ(report.failed, std::vector<std::int64_t>{a});
  EXPECT_TRUE(report.requeued.empty());
  EXPECT_EQ(store().find(a)->state, JobState::kFailed);
  EXPECT_NE(store().find(a)->error.find("max-attempts"), std::string::npos);
  EXPECT_EQ(store().find(c)->state, JobState::kQueued);  // never started: untouched
}

TEST_P(JobStoreContract, RecoveryBelowLimitRequeuesAndCountsTheAttempt) {
  const auto id = submit("1");
  const Lease first = store().claim_next(claim_as("w1"))->lease;
  store().update_progress(first, JobProgress{5, 0.1, 0.2});
  store_ = db_->open();
  const RecoveryReport report = store().recover_interrupted(3);
  EXPECT_EQ(report.requeued, std::vector<std::int64_t>{id});
  auto job = store().find(id);
  EXPECT_EQ(job->state, JobState::kQueued);
  EXPECT_EQ(job->attempts, 1);
  EXPECT_FALSE(job->progress);
  EXPECT_FALSE(job->started_at_ms);
  auto claimed = store().claim_next(claim_as("w1"));  // even the same worker name
  ASSERT_TRUE(claimed);
  EXPECT_EQ(claimed->job.attempts, 2);
  // The interrupted attempt can no longer complete the job.
  EXPECT_FALSE(store().complete_succeeded(first, "{}", ""));
  EXPECT_TRUE(store().complete_succeeded(claimed->lease, "{}", ""));
}

TEST_P(JobStoreContract, ShutdownRequeueDoesNotCountTheAttempt) {
  const auto id = submit("1");
  const Lease lease = store().claim_next(claim_as())->lease;
  EXPECT_TRUE(store().requeue(lease));
  auto job = store().find(id);
  EXPECT_EQ(job->state, JobState::kQueued);
  EXPECT_EQ(job->attempts, 0);
  EXPECT_FALSE(job->started_at_ms);
  EXPECT_FALSE(store().requeue(lease));  // only once
  EXPECT_EQ(store().claim_next(claim_as("w2"))->job.attempts, 1);
}

TEST_P(JobStoreContract, RequeueAfterCancelRequestCancels) {
  const auto id = submit("1");
  const Lease lease = store().claim_next(claim_as())->lease;
  ASSERT_EQ(store().cancel(id).kind, CancelOutcome::Kind::kRequested);
  EXPECT_TRUE(store().requeue(lease));
  EXPECT_EQ(store().find(id)->state, JobState::kCancelled);
}

TEST_P(JobStoreContract, RenewedLeasesDoNotExpire) {
  const auto id = submit("1");
  const Lease lease = store().claim_next(claim_as("w1", 1min))->lease;
  EXPECT_TRUE(store().requeue_expired_leases(3).requeued.empty());
  EXPECT_EQ(store().renew_lease(lease, 1min), LeaseStatus::kHeld);
  EXPECT_TRUE(store().requeue_expired_leases(3).requeued.empty());
  EXPECT_EQ(store().find(id)->state, JobState::kRunning);
}

// A worker killed with its job: the lease runs out, whoever notices puts the job back with the
// attempt counted, another worker claims it, and the first one's late result is refused.
TEST_P(JobStoreContract, ExpiredLeaseIsRequeuedAndTheLateWorkerRefused) {
  const auto id = submit("1");
  const auto other = submit("2");
  const Lease dead = store().claim_next(claim_as("dead", 50ms))->lease;
  const Lease alive = store().claim_next(claim_as("alive", 10min))->lease;
  ASSERT_EQ(alive.job_id, other);
  std::this_thread::sleep_for(200ms);  // at least the 50 ms lease: expired on any clock
  auto noticing = db_->open();         // any other process notices
  const RecoveryReport report = noticing->requeue_expired_leases(3);
  EXPECT_EQ(report.requeued, std::vector<std::int64_t>{id});
  EXPECT_TRUE(report.failed.empty());
  EXPECT_EQ(store().find(other)->state, JobState::kRunning);  // its lease is still valid
  EXPECT_EQ(store().find(id)->attempts, 1);                   // the lost attempt counts

  const auto retry = noticing->claim_next(claim_as("second"));
  ASSERT_TRUE(retry);
  EXPECT_EQ(retry->job.id, id);
  EXPECT_EQ(retry->lease.attempt, 2);
  // The first worker was only slow, not dead: everything it does now is refused.
  EXPECT_EQ(store().renew_lease(dead, 1min), LeaseStatus::kLost);
  EXPECT_FALSE(store().complete_succeeded(dead, R"({"late":true})", "late"));
  EXPECT_TRUE(store().complete_succeeded(retry->lease, R"({"late":false})", "v"));
  EXPECT_EQ(store().result_json(id), R"({"late":false})");
  EXPECT_TRUE(noticing->requeue_expired_leases(3).requeued.empty());  // nothing twice
}

TEST_P(JobStoreContract, ExpiredLeasesFailAtMaxAttemptsAndHonourCancels) {
  const auto doomed = submit("1");
  const auto cancelled = submit("2");
  store().claim_next(claim_as("a", 1ms));
  store().claim_next(claim_as("b", 1ms));
  ASSERT_EQ(store().cancel(cancelled).kind, CancelOutcome::Kind::kRequested);
  std::this_thread::sleep_for(100ms);
  const RecoveryReport report = store().requeue_expired_leases(1);
  EXPECT_EQ(report.failed, std::vector<std::int64_t>{doomed});
  EXPECT_EQ(report.cancelled, std::vector<std::int64_t>{cancelled});
  EXPECT_TRUE(report.requeued.empty());
  const Job failed = *store().find(doomed);
  EXPECT_EQ(failed.state, JobState::kFailed);
  EXPECT_NE(failed.error.find("max-attempts"), std::string::npos) << failed.error;
  EXPECT_TRUE(failed.finished_at_ms);
  EXPECT_EQ(store().find(cancelled)->state, JobState::kCancelled);
}

TEST_P(JobStoreContract, RetentionDeletesOnlyOldFinishedJobs) {
  const auto finished = submit("1");
  const auto queued = submit("2");
  ASSERT_TRUE(store().complete_succeeded(store().claim_next(claim_as())->lease, "{}", ""));
  const std::int64_t finished_at = *store().find(finished)->finished_at_ms;
  EXPECT_EQ(store().delete_finished_before(finished_at), 0);  // not older than the cut-off
  EXPECT_EQ(store().delete_finished_before(finished_at + 1), 1);
  EXPECT_FALSE(store().find(finished));
  EXPECT_TRUE(store().find(queued));  // unfinished jobs are never deleted
  EXPECT_EQ(store().delete_finished_before(now_unix_ms() + 1'000'000), 0);
}

TEST_P(JobStoreContract, RetentionDeletesInBatchesUntilDone) {
  for (int i = 0; i < 230; ++i) {
    submit(std::to_string(i));
    ASSERT_TRUE(store().complete_failed(store().claim_next(claim_as())->lease, "x"));
  }
  EXPECT_EQ(store().delete_finished_before(now_unix_ms() + 1'000'000), 230);
  EXPECT_EQ(store().count_by_state()[JobState::kFailed], 0);
}

TEST_P(JobStoreContract, ConcurrentSubmitsWithOneKeyCreateOneJob) {
  constexpr int kThreads = 6;
  std::vector<std::unique_ptr<JobStore>> stores;
  for (int i = 0; i < kThreads; ++i) stores.push_back(db_->open());
  std::atomic<int> created{0}, replayed{0}, errors{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) {
    threads.emplace_back([&, i] {
      for (int k = 0; k < 10; ++k) {
        try {
          const auto out =
              stores[i]->submit(make_job("same", "key-" + std::to_string(k)), kUnlimited);
          (out.kind == SubmitOutcome::Kind::kCreated ? created : replayed)++;
        } catch (const StoreError&) {
          ++errors;
        }
      }
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(errors.load(), 0);
  EXPECT_EQ(created.load(), 10);
  EXPECT_EQ(replayed.load(), 10 * (kThreads - 1));
  EXPECT_EQ(store().count_by_state()[JobState::kQueued], 10);
}

// Submitters, claimers and readers on separate threads and separate store objects (separate
// processes, as far as the database can tell): every job is claimed exactly once and no call
// fails (for SQLite: no "database is locked").
TEST_P(JobStoreContract, ClaimsAreExclusiveUnderConcurrency) {
  constexpr int kSubmitters = 4;
  constexpr int kPerSubmitter = 50;
  constexpr int kWorkers = 4;
  std::vector<std::unique_ptr<JobStore>> stores;
  for (int i = 0; i < kSubmitters + kWorkers; ++i) stores.push_back(db_->open());
  std::atomic<int> errors{0};
  std::atomic<int> completed{0};
  std::mutex claimed_mutex;
  std::multiset<std::int64_t> claimed_ids;

  std::vector<std::thread> threads;
  for (int s = 0; s < kSubmitters; ++s) {
    threads.emplace_back([&, s] {
      JobStore& st = *stores[s];
      for (int i = 0; i < kPerSubmitter; ++i) {
        try {
          const std::string key = "k" + std::to_string(s) + "-" + std::to_string(i);
          auto out = st.submit(make_job(std::to_string(i), key), kUnlimited);
          if (out.kind != SubmitOutcome::Kind::kCreated) ++errors;
          // Every request is retried once, as a client would after a timeout.
          if (st.submit(make_job(std::to_string(i), key), kUnlimited).kind !=
              SubmitOutcome::Kind::kReplayed) {
            ++errors;
          }
          st.find(out.job->id);
        } catch (const StoreError&) {
          ++errors;
        }
      }
    });
  }
  for (int w = 0; w < kWorkers; ++w) {
    threads.emplace_back([&, w] {
      JobStore& st = *stores[kSubmitters + w];
      const std::string worker = "w" + std::to_string(w);
      while (completed.load() < kSubmitters * kPerSubmitter) {
        try {
          auto job = st.claim_next(claim_as(worker));
          if (!job) {
            std::this_thread::yield();
            continue;
          }
          {
            std::lock_guard lock(claimed_mutex);
            claimed_ids.insert(job->job.id);
          }
          st.update_progress(job->lease, JobProgress{1, 0.5, 0.5});
          if (st.renew_lease(job->lease, 1min) != LeaseStatus::kHeld) ++errors;
          if (!st.complete_succeeded(job->lease, "{}", "")) ++errors;
          ++completed;
        } catch (const StoreError& e) {
          ADD_FAILURE() << e.what();
          ++errors;
          return;
        }
      }
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(errors.load(), 0);
  EXPECT_EQ(completed.load(), kSubmitters * kPerSubmitter);
  EXPECT_EQ(claimed_ids.size(), static_cast<std::size_t>(kSubmitters * kPerSubmitter));
  EXPECT_EQ(std::set<std::int64_t>(claimed_ids.begin(), claimed_ids.end()).size(),
            claimed_ids.size());  // nobody claimed a job twice
  EXPECT_EQ(store().count_by_state()[JobState::kSucceeded], kSubmitters * kPerSubmitter);
}

TEST_P(JobStoreContract, PingAndCounts) {
  EXPECT_NO_THROW(store().ping());
  const auto counts = store().count_by_state();
  EXPECT_EQ(counts.size(), kAllJobStates.size());
  for (const auto& [state, n] : counts) EXPECT_EQ(n, 0);
}

TEST_P(JobStoreContract, WorkersDeclareTheirBudgetAndTheSmallestLiveOneIsAdmittedAgainst) {
  EXPECT_FALSE(store().declared_worker_budget());  // no worker ever declared one
  store().declare_worker_budget("host:1:a", std::size_t{4} << 30);
  EXPECT_EQ(store().declared_worker_budget(), std::size_t{4} << 30);
  store().declare_worker_budget("host:2:b", std::size_t{2} << 30);
  EXPECT_EQ(store().declared_worker_budget(), std::size_t{2} << 30);  // any may claim any job
  store().declare_worker_budget("host:2:b", std::size_t{8} << 30);    // renewed with another
  EXPECT_EQ(store().declared_worker_budget(), std::size_t{4} << 30);
}

}  // namespace
}  // namespace fosls::service::testing
