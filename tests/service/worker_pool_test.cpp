// Worker threads over a real SQLite store with a fake solver step: outcomes, exceptions,
// cancellation, shutdown and progress throttling.

#include "worker_pool.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <sstream>
#include <thread>

#include "fake_job_runner.hpp"
#include "forwarding_store.hpp"
#include "request_checks.hpp"
#include "sqlite_job_store.hpp"
#include "temp_dir.hpp"

namespace fosls::service {
namespace {

using testing::fake_job_runner;
using testing::TempDir;

/// Counts progress writes on the way to the real store.
class CountingStore final : public testing::ForwardingStore {
 public:
  using ForwardingStore::ForwardingStore;
  std::atomic<int> progress_writes{0};
  std::atomic<bool> fail_results{false};  ///< complete_with_result throws, like a full disk

  void update_progress(const Lease& l, const JobProgress& p) override {
    ++progress_writes;
    ForwardingStore::update_progress(l, p);
  }
  bool complete_with_result(const Lease& l, const SolveRecord& r) override {
    if (fail_results) throw StoreError("string or blob too big");
    return ForwardingStore::complete_with_result(l, r);
  }
};

class WorkerPoolTest : public ::testing::Test {
 protected:
  TempDir dir_;
  SqliteJobStore store_{dir_.file("jobs.db")};
  std::ostringstream log_text_;
  EventLog log_{log_text_};
  Metrics metrics_;

  std::int64_t submit(const nlohmann::json& body) {
    NewJob job;
    job.name = "t";
    job.case_json = body.dump();
    job.body_hash = sha256_hex(job.case_json);
    return store_.submit(job, 1000).job->id;
  }

  /// Polls until the job satisfies `done`; the bound only stops a broken test from hanging.
  Job wait_for(JobStore& store, std::int64_t id, const std::function<bool(const Job&)>& done) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    for (;;) {
      auto job = store.find(id);
      if (job && done(*job)) return *job;
      if (std::chrono::steady_clock::now() > give_up) {
        ADD_FAILURE() << "job " << id << " did not reach the expected state";
        return job.value_or(Job{});
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  Job wait_state(std::int64_t id, JobState state) {
    return wait_for(store_, id, [state](const Job& j) { return j.state == state; });
  }

  static WorkerPoolOptions options(int workers) {
    WorkerPoolOptions o;
    o.workers = workers;
    o.idle_poll = std::chrono::milliseconds(50);
    return o;
  }
};

TEST_F(WorkerPoolTest, SolvesQueuedJobsAndStoresResults) {
  const auto a = submit({{"mode", "ok"}, {"iterations", 4}});
  const auto b = submit({{"mode", "ok"}, {"iterations", 2}});
  WorkerPool pool(store_, fake_job_runner, log_, metrics_, options(2));
  pool.start();
  const Job ja = wait_state(a, JobState::kSucceeded);
  wait_state(b, JobState::kSucceeded);
  EXPECT_EQ(ja.attempts, 1);
  ASSERT_TRUE(ja.progress);
  EXPECT_EQ(ja.progress->iteration, 4);  // the last iteration is always written
  auto result = nlohmann::json::parse(*store_.result_json(a));
  EXPECT_EQ(result["iterations"], 4);
  EXPECT_EQ(store_.vtu(a), "<VTKFile type=\"UnstructuredGrid\"/>");
  pool.begin_shutdown();
  pool.join();
  EXPECT_NE(log_text_.str().find("\"to\":\"succeeded\""), std::string::npos);
  MetricsSnapshot snapshot;
  EXPECT_NE(metrics_.render(snapshot).find("fosls_job_run_seconds_count{outcome=\"succeeded\"} 2"),
            std::string::npos);
}

TEST_F(WorkerPoolTest, ExceptionsAndFailuresFailTheJobNotTheWorker) {
  const auto thrown = submit({{"mode", "throw"}});
  const auto other = submit({{"mode", "throw_other"}});
  const auto failed = submit({{"mode", "fail"}});
  const auto ok = submit({{"mode", "ok"}});
  WorkerPool pool(store_, fake_job_runner, log_, metrics_, options(1));
  pool.start();
  EXPECT_NE(wait_state(thrown, JobState::kFailed).error.find("boom from the fake solver"),
            std::string::npos);
  EXPECT_NE(wait_state(other, JobState::kFailed).error.find("unknown exception"),
            std::string::npos);
  EXPECT_EQ(wait_state(failed, JobState::kFailed).error, "/solver/tolerance: fake failure");
  wait_state(ok, JobState::kSucceeded);  // the single worker survived all three
}

TEST_F(WorkerPoolTest, CancellingARunningJobFreesTheWorker) {
  const auto endless = submit({{"mode", "until_cancel"}});
  const auto next = submit({{"mode", "ok"}});
  WorkerPool pool(store_, fake_job_runner, log_, metrics_, options(1));
  pool.start();
  wait_for(store_, endless, [](const Job& j) { return j.progress.has_value(); });
  ASSERT_EQ(store_.cancel(endless).kind, CancelOutcome::Kind::kRequested);
  pool.request_cancel(endless);
  const Job cancelled = wait_state(endless, JobState::kCancelled);
  EXPECT_TRUE(cancelled.finished_at_ms);
  wait_state(next, JobState::kSucceeded);
}

TEST_F(WorkerPoolTest, CancelArrivingBeforeTheWorkerRegistersIsNotLost) {
  const auto id = submit({{"mode", "until_cancel"}});
  WorkerPool pool(store_, fake_job_runner, log_, metrics_, options(1));
  // The HTTP thread saw the job running and asked to cancel before its worker registered it.
  pool.request_cancel(id);
  pool.start();
  wait_state(id, JobState::kCancelled);
}

TEST_F(WorkerPoolTest, ShutdownPutsRunningJobsBackWithoutCountingTheAttempt) {
  const auto id = submit({{"mode", "until_cancel"}});
  {
    WorkerPool pool(store_, fake_job_runner, log_, metrics_, options(1));
    pool.start();
    wait_for(store_, id, [](const Job& j) { return j.progress.has_value(); });
    pool.begin_shutdown();
    pool.join();
  }
  const Job job = *store_.find(id);
  EXPECT_EQ(job.state, JobState::kQueued);
  EXPECT_EQ(job.attempts, 0);
  EXPECT_FALSE(job.started_at_ms);
}

// The cancel arrives through the store only (an API process on another host took it): the
// heartbeat reads it and stops the solve.
TEST_F(WorkerPoolTest, CancelRequestedThroughTheStoreReachesTheWorker) {
  const auto id = submit({{"mode", "until_cancel"}});
  WorkerPoolOptions o = options(1);
  o.heartbeat_interval = std::chrono::milliseconds(20);
  WorkerPool pool(store_, fake_job_runner, log_, metrics_, o);
  pool.start();
  wait_for(store_, id, [](const Job& j) { return j.progress.has_value(); });
  ASSERT_EQ(store_.cancel(id).kind, CancelOutcome::Kind::kRequested);  // no request_cancel
  const Job cancelled = wait_state(id, JobState::kCancelled);
  EXPECT_EQ(cancelled.attempts, 1);
}

// The lease is taken away (expired and re-queued by another process while this worker was
// cut off): the worker stops the solve and stores nothing.
TEST_F(WorkerPoolTest, ALostLeaseStopsTheSolveAndStoresNothing) {
  const auto id = submit({{"mode", "until_cancel"}});
  WorkerPoolOptions o = options(1);
  o.heartbeat_interval = std::chrono::milliseconds(20);
  o.lease_duration = std::chrono::milliseconds(60000);
  WorkerPool pool(store_, fake_job_runner, log_, metrics_, o);
  pool.start();
  wait_for(store_, id, [](const Job& j) { return j.progress.has_value(); });
  // What another process's reaper does once the lease has expired.
  ASSERT_EQ(store_.recover_interrupted(3).requeued, std::vector<std::int64_t>{id});
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (log_text_.str().find("\"to\":\"abandoned\"") == std::string::npos &&
         std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  pool.begin_shutdown();
  pool.join();
  EXPECT_NE(log_text_.str().find("lease_lost"), std::string::npos) << log_text_.str();
  const Job job = *store_.find(id);
  // The worker re-claimed it after giving it up, then shutdown put it back uncounted; or it is
  // still queued from the recovery. Either way: queued, one counted attempt, no result.
  EXPECT_EQ(job.state, JobState::kQueued);
  EXPECT_EQ(job.attempts, 1);
  EXPECT_FALSE(store_.result_json(id));
}

TEST_F(WorkerPoolTest, ZeroWorkersIsAnApiOnlyProcess) {
  const auto id = submit({{"mode", "ok"}});
  WorkerPool pool(store_, fake_job_runner, log_, metrics_, options(0));
  pool.start();
  pool.notify_job_available();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(pool.size(), 0);
  EXPECT_EQ(store_.find(id)->state, JobState::kQueued);  // nobody here solves
  pool.begin_shutdown();
  pool.join();
}

TEST_F(WorkerPoolTest, ProgressWritesAreThrottled) {
  CountingStore counting(store_);
  const auto id = submit({{"mode", "ok"}, {"iterations", 5000}});
  WorkerPoolOptions o = options(1);
  o.progress_interval = std::chrono::hours(1);
  WorkerPool pool(counting, fake_job_runner, log_, metrics_, o);
  pool.start();
  const Job job = wait_state(id, JobState::kSucceeded);
  EXPECT_EQ(job.progress->iteration, 5000);
  EXPECT_EQ(counting.progress_writes.load(), 2);  // the first iteration and the final one
}

TEST_F(WorkerPoolTest, AResultThatCannotBeStoredFailsTheJobInsteadOfLeavingItRunning) {
  CountingStore failing(store_);
  failing.fail_results = true;
  const auto id = submit({{"mode", "ok"}});
  WorkerPoolOptions o = options(1);
  o.store_retry_delay = std::chrono::milliseconds(1);
  WorkerPool pool(failing, fake_job_runner, log_, metrics_, o);
  pool.start();
  const Job job = wait_state(id, JobState::kFailed);
  EXPECT_NE(job.error.find("could not be stored: string or blob too big"), std::string::npos);
  EXPECT_FALSE(store_.result_json(id));
}

TEST_F(WorkerPoolTest, AnUnconvergedSolveSucceedsSayingSo) {
  const auto converged = submit({{"mode", "ok"}});
  const auto unconverged = submit({{"mode", "ok"}, {"converged", false}});
  WorkerPool pool(store_, fake_job_runner, log_, metrics_, options(1));
  pool.start();
  const Job good = wait_state(converged, JobState::kSucceeded);
  const Job bad = wait_state(unconverged, JobState::kSucceeded);
  EXPECT_EQ(good.convergence.converged, std::optional<bool>(true));
  EXPECT_EQ(good.convergence.stop_reason, "converged");
  EXPECT_EQ(bad.convergence.converged, std::optional<bool>(false));
  EXPECT_EQ(bad.convergence.stop_reason, "max_iterations");
  EXPECT_EQ(store_.count_not_converged(), 1);
  pool.begin_shutdown();
  pool.join();
  const std::string text = metrics_.render(MetricsSnapshot{});
  EXPECT_NE(text.find("fosls_solves_total{stop_reason=\"max_iterations\"} 1"), std::string::npos)
      << text;
  EXPECT_NE(text.find("fosls_solves_total{stop_reason=\"converged\"} 1"), std::string::npos);
}

TEST_F(WorkerPoolTest, FailUnconvergedFailsTheJobAndKeepsItsResult) {
  const auto converged = submit({{"mode", "ok"}});
  const auto unconverged = submit({{"mode", "ok"}, {"converged", false}});
  WorkerPoolOptions o = options(1);
  o.fail_unconverged = true;
  WorkerPool pool(store_, fake_job_runner, log_, metrics_, o);
  pool.start();
  wait_state(converged, JobState::kSucceeded);
  const Job bad = wait_state(unconverged, JobState::kFailed);
  EXPECT_NE(bad.error.find("without converging (stop_reason max_iterations)"), std::string::npos)
      << bad.error;
  EXPECT_NE(bad.error.find("--fail-unconverged"), std::string::npos);
  EXPECT_EQ(bad.convergence.converged, std::optional<bool>(false));
  ASSERT_TRUE(store_.result_json(unconverged));
  EXPECT_EQ(nlohmann::json::parse(*store_.result_json(unconverged))["converged"], false);
  EXPECT_TRUE(store_.vtu(unconverged));
}

}  // namespace
}  // namespace fosls::service
