// One contract, two stores: every test runs against SQLite and against PostgreSQL (a throwaway
// server started by the test process). Lifecycle, results and progress, idempotency, the queue
// bound, cancel, delete and pagination here; recovery, leases (renewal, expiry, late completion
// refused), retention and claim exclusivity with many threads in job_store_recovery_test.cpp.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gzip.hpp"
#include "job_store_contract.hpp"

// In the support's namespace: the fixture, claim_as, make_job and kUnlimited without usings.
namespace fosls::service::testing {
namespace {

using namespace std::chrono_literals;

TEST_P(JobStoreContract, SubmitClaimSucceedStoresResultOnce) {
  const SubmitOutcome submitted = store().submit(make_job(R"({"a":1})"), kUnlimited);
  ASSERT_EQ(submitted.kind, SubmitOutcome::Kind::kCreated);
  const std::int64_t id = submitted.job->id;
  EXPECT_EQ(submitted.job->state, JobState::kQueued);
  EXPECT_EQ(submitted.job->attempts, 0);
  EXPECT_GT(submitted.job->created_at_ms, 0);

  auto claimed = store().claim_next(claim_as("w1"));
  ASSERT_TRUE(claimed);
  EXPECT_EQ(claimed->job.id, id);
  EXPECT_EQ(claimed->job.state, JobState::kRunning);
  EXPECT_EQ(claimed->job.attempts, 1);
  EXPECT_TRUE(claimed->job.started_at_ms);
  EXPECT_EQ(claimed->case_json, R"({"a":1})");
  EXPECT_EQ(claimed->lease.job_id, id);
  EXPECT_EQ(claimed->lease.attempt, 1);
  EXPECT_EQ(claimed->lease.worker_id, "w1");
  EXPECT_FALSE(store().claim_next(claim_as("w2")));  // nothing else queued

  const Lease& lease = claimed->lease;
  store().update_progress(lease, JobProgress{7, 1e-3, -2.5});
  auto running = store().find(id);
  ASSERT_TRUE(running && running->progress);
  EXPECT_EQ(running->progress->iteration, 7);
  EXPECT_DOUBLE_EQ(running->progress->kkt_residual, 1e-3);
  EXPECT_DOUBLE_EQ(running->progress->energy, -2.5);

  const std::string vtu = "<VTKFile>" + std::string(100000, 'x') + "</VTKFile>";
  EXPECT_TRUE(store().complete_succeeded(lease, R"({"converged":true})", vtu));
  // A second completion of the same attempt is refused: a result is written once.
  EXPECT_FALSE(store().complete_succeeded(lease, R"({"converged":false})", ""));
  EXPECT_FALSE(store().complete_failed(lease, "late"));
  auto done = store().find(id);
  EXPECT_EQ(done->state, JobState::kSucceeded);
  EXPECT_TRUE(done->finished_at_ms);
  EXPECT_GE(*done->finished_at_ms, *done->started_at_ms);
  EXPECT_EQ(store().result_json(id), R"({"converged":true})");
  EXPECT_EQ(store().case_json(id), R"({"a":1})");
  EXPECT_EQ(done->convergence.converged, std::optional<bool>(true));  // read from the result
  EXPECT_EQ(store().vtu(id), vtu);  // stored compressed, served as written
  EXPECT_FALSE(store().result_json(id + 1));
  EXPECT_FALSE(store().vtu(id + 1));
  EXPECT_FALSE(store().case_json(id + 1));
}

// --fail-unconverged: the job fails, its result and how the solve stopped are kept, and the
// listing and the metrics count it.
TEST_P(JobStoreContract, AFailedJobCanKeepAResultAndItsConvergence) {
  const auto id = submit("{}");
  const auto plain = submit("{}");
  const Lease lease = store().claim_next(claim_as())->lease;
  SolveRecord record{
      R"({"converged":false})", "<VTKFile/>", {false, "max_iterations"}, "did not converge"};
  EXPECT_TRUE(store().complete_with_result(lease, record));
  const Lease other = store().claim_next(claim_as())->lease;
  EXPECT_TRUE(store().complete_succeeded(other, R"({"no":"convergence fields"})", ""));
  const auto job = store().find(id);
  EXPECT_EQ(job->state, JobState::kFailed);
  EXPECT_EQ(job->error, "did not converge");
  EXPECT_EQ(job->convergence.converged, std::optional<bool>(false));
  EXPECT_EQ(job->convergence.stop_reason, "max_iterations");
  EXPECT_EQ(store().result_json(id), R"({"converged":false})");
  EXPECT_EQ(store().vtu(id), "<VTKFile/>");
  const auto listed = store().list(JobListQuery{});
  ASSERT_EQ(listed.jobs.size(), 2u);
  EXPECT_EQ(listed.jobs[1].convergence.stop_reason, "max_iterations");
  EXPECT_FALSE(listed.jobs[0].convergence.converged);  // a result without the field
  EXPECT_EQ(listed.jobs[0].id, plain);
  EXPECT_EQ(store().count_not_converged(), 1);
  JobListQuery unconverged;
  unconverged.converged = false;
  const auto only = store().list(unconverged);
  ASSERT_EQ(only.jobs.size(), 1u);
  EXPECT_EQ(only.jobs[0].id, id);
  unconverged.converged = true;
  EXPECT_TRUE(store().list(unconverged).jobs.empty());  // the other job's result says nothing
}

TEST_P(JobStoreContract, NonFiniteProgressIsStoredAsUnknown) {
  const auto id = submit("{}");
  const Lease lease = store().claim_next(claim_as())->lease;
  store().update_progress(lease, JobProgress{2, std::nan(""), INFINITY});
  const auto job = store().find(id);
  ASSERT_TRUE(job->progress);
  EXPECT_EQ(job->progress->iteration, 2);
  EXPECT_TRUE(std::isnan(job->progress->kkt_residual));
  EXPECT_TRUE(std::isnan(job->progress->energy));
}

// Which solve of a multi-solve job the progress is of; a database from before the columns
// (the latest step undone) is migrated, its progress read as step 0 of a number not known.
TEST_P(JobStoreContract, ProgressStepsRoundTripAndSurviveAnOlderSchema) {
  const auto id = submit("{}");
  const Lease lease = store().claim_next(claim_as())->lease;
  store().update_progress(lease, JobProgress{4, 0.5, -1.0, 2, 3});
  const auto job = store().find(id);
  ASSERT_TRUE(job->progress);
  EXPECT_EQ(job->progress->step, 2);
  EXPECT_EQ(job->progress->steps, 3);
  EXPECT_EQ(job_to_json(*job)["progress"]["steps"], 3);
  store().update_progress(lease, JobProgress{1, 0.5, -1.0, 5, 0});  // steps not known
  EXPECT_EQ(job_to_json(*store().find(id))["progress"]["steps"], nullptr);

  store_.reset();
  {
    auto c = db_->connect();
    const auto latest = c->query("SELECT max(version) AS v FROM schema_migrations")[0].int64("v");
    // Back to the schema before progress steps (and the time estimates that came after).
    c->exec(
        "ALTER TABLE jobs DROP COLUMN progress_step; "
        "ALTER TABLE jobs DROP COLUMN progress_steps; "
        "ALTER TABLE jobs DROP COLUMN time_estimate_s; "
        "DELETE FROM schema_migrations WHERE version >= " +
        std::to_string(latest - 1));
    if (db_->kind() == "sqlite") c->exec("PRAGMA user_version = " + std::to_string(latest - 2));
  }
  store_ = db_->open();
  const auto migrated = store().find(id);
  ASSERT_TRUE(migrated && migrated->progress);
  EXPECT_EQ(migrated->progress->iteration, 1);
  EXPECT_EQ(migrated->progress->step, 0);
  EXPECT_EQ(job_to_json(*migrated)["progress"]["steps"], nullptr);
  store().update_progress(lease, JobProgress{2, 0.5, -1.0, 1, 3});
  EXPECT_EQ(job_to_json(*store().find(id))["progress"]["step"], 1);
  EXPECT_TRUE(store().complete_succeeded(lease, "{}", ""));
}

TEST_P(JobStoreContract, TheTimeEstimateGoesFromSubmitToClaim) {
  NewJob estimated = make_job(R"({"a":1})");
  estimated.time_estimate_seconds = 12.5;
  store().submit(estimated, kUnlimited);
  store().submit(make_job(R"({"a":2})"), kUnlimited);  // admitted without an estimate
  const auto first = store().claim_next(claim_as());
  ASSERT_TRUE(first);
  EXPECT_EQ(first->time_estimate_seconds, std::optional<double>(12.5));
  const auto second = store().claim_next(claim_as());
  ASSERT_TRUE(second);
  EXPECT_FALSE(second->time_estimate_seconds);

  // A job queued before the column existed is claimed without one.
  store_.reset();
  {
    auto c = db_->connect();
    const auto latest = c->query("SELECT max(version) AS v FROM schema_migrations")[0].int64("v");
    c->exec(
        "ALTER TABLE jobs DROP COLUMN time_estimate_s; "
        "DELETE FROM schema_migrations WHERE version = " +
        std::to_string(latest));
    if (db_->kind() == "sqlite") c->exec("PRAGMA user_version = " + std::to_string(latest - 1));
    c->exec(
        "INSERT INTO jobs (name, state, case_json, body_hash, created_at) "
        "VALUES ('old', 'queued', '{}', 'h', 0)");
  }
  store_ = db_->open();
  const auto old = store().claim_next(claim_as());
  ASSERT_TRUE(old);
  EXPECT_EQ(old->case_json, "{}");
  EXPECT_FALSE(old->time_estimate_seconds);
}

TEST_P(JobStoreContract, TheVtuIsReadInPartsOfItsStoredBytes) {
  const auto id = submit("{}");
  const Lease lease = store().claim_next(claim_as())->lease;
  std::string vtu = "<VTKFile>";
  for (int i = 0; vtu.size() < 300000; ++i) vtu += std::to_string(i * 0.37) + " ";
  ASSERT_TRUE(store().complete_succeeded(lease, "{}", vtu + "</VTKFile>"));
  const auto stored = store().stored_vtu(id);
  ASSERT_TRUE(stored);
  EXPECT_TRUE(stored->gzip);
  EXPECT_GT(stored->bytes, 1000);
  EXPECT_LT(stored->bytes, static_cast<std::int64_t>(vtu.size()));
  std::string joined;  // odd part sizes, the last one past the end
  for (std::int64_t at = 0; at < stored->bytes; at += 7777) {
    const auto part = store().stored_vtu_bytes(id, at, 7777);
    ASSERT_TRUE(part);
    EXPECT_EQ(static_cast<std::int64_t>(part->size()),
              std::min<std::int64_t>(7777, stored->bytes - at));
    joined += *part;
  }
  EXPECT_EQ(static_cast<std::int64_t>(joined.size()), stored->bytes);
  EXPECT_EQ(gzip_decompress(joined), vtu + "</VTKFile>");
  EXPECT_EQ(gzip_recorded_size(joined.substr(joined.size() - 4)), vtu.size() + 10);
  EXPECT_EQ(store().stored_vtu_bytes(id, stored->bytes, 10), std::optional<std::string>(""));
  EXPECT_FALSE(store().stored_vtu(id + 1));
  EXPECT_FALSE(store().stored_vtu_bytes(id + 1, 0, 10));
}

TEST_P(JobStoreContract, TheResultIsReadInPartsOfItsBytes) {
  const auto id = submit("{}");
  const Lease lease = store().claim_next(claim_as())->lease;
  std::string result = R"({"converged":true,"name":"Prüfung σ ✓","steps":[)";
  for (int i = 0; result.size() < 100000; ++i) result += R"({"k":)" + std::to_string(i) + "},";
  result += R"({"k":-1}]})";
  ASSERT_TRUE(store().complete_succeeded(lease, result, "<VTKFile/>"));
  EXPECT_EQ(store().result_json_size(id), std::optional<std::int64_t>(result.size()));
  std::string joined;  // odd part sizes that cut multi-byte characters, the last past the end
  for (std::int64_t at = 0; at < static_cast<std::int64_t>(result.size()); at += 37)
    joined += store().result_json_bytes(id, at, 37).value_or("<gone>");
  EXPECT_EQ(joined, result);
  EXPECT_EQ(store().result_json_bytes(id, result.size(), 10), std::optional<std::string>(""));
  EXPECT_FALSE(store().result_json_size(id + 1));
  EXPECT_FALSE(store().result_json_bytes(id + 1, 0, 10));
}

TEST_P(JobStoreContract, OnlyTheLeaseHolderChangesARunningJob) {
  const auto id = submit("{}");
  const Lease lease = store().claim_next(claim_as("w1"))->lease;
  Lease wrong_attempt = lease;
  wrong_attempt.attempt = 2;
  Lease wrong_worker = lease;
  wrong_worker.worker_id = "w2";
  for (const Lease& other : {wrong_attempt, wrong_worker}) {
    store().update_progress(other, JobProgress{3, 1, 1});
    EXPECT_EQ(store().renew_lease(other, 1min), LeaseStatus::kLost);
    EXPECT_FALSE(store().complete_succeeded(other, "{}", ""));
    EXPECT_FALSE(store().complete_failed(other, "x"));
    EXPECT_FALSE(store().complete_cancelled(other));
    EXPECT_FALSE(store().requeue(other));
  }
  EXPECT_FALSE(store().find(id)->progress);
  EXPECT_EQ(store().find(id)->state, JobState::kRunning);
  EXPECT_FALSE(store().result_json(id));
}

TEST_P(JobStoreContract, FailedJobKeepsItsError) {
  const auto id = submit("{}");
  const Lease lease = store().claim_next(claim_as())->lease;
  EXPECT_TRUE(store().complete_failed(lease, "/weights/c1: must be positive"));
  auto job = store().find(id);
  EXPECT_EQ(job->state, JobState::kFailed);
  EXPECT_EQ(job->error, "/weights/c1: must be positive");
  EXPECT_TRUE(job->finished_at_ms);
  EXPECT_FALSE(store().result_json(id));
}

TEST_P(JobStoreContract, ClaimsOldestFirst) {
  const auto first = submit("1");
  const auto second = submit("2");
  EXPECT_EQ(store().claim_next(claim_as("a"))->job.id, first);
  EXPECT_EQ(store().claim_next(claim_as("b"))->job.id, second);
}

TEST_P(JobStoreContract, IdempotencyKeyReplaysSameBodyAndRejectsDifferentBody) {
  const auto created = store().submit(make_job(R"({"x":1})", "key-1"), kUnlimited);
  ASSERT_EQ(created.kind, SubmitOutcome::Kind::kCreated);
  const auto replay = store().submit(make_job(R"({"x":1})", "key-1"), kUnlimited);
  EXPECT_EQ(replay.kind, SubmitOutcome::Kind::kReplayed);
  EXPECT_EQ(replay.job->id, created.job->id);
  const auto conflict = store().submit(make_job(R"({"x":2})", "key-1"), kUnlimited);
  EXPECT_EQ(conflict.kind, SubmitOutcome::Kind::kKeyConflict);
  EXPECT_EQ(conflict.job->id, created.job->id);
  const auto other = store().submit(make_job(R"({"x":1})", "key-2"), kUnlimited);
  EXPECT_EQ(other.kind, SubmitOutcome::Kind::kCreated);
  EXPECT_NE(other.job->id, created.job->id);
  EXPECT_EQ(store().count_by_state()[JobState::kQueued], 2);
}

TEST_P(JobStoreContract, QueueLimitCountsOnlyQueuedJobs) {
  EXPECT_EQ(store().submit(make_job("1"), 2).kind, SubmitOutcome::Kind::kCreated);
  EXPECT_EQ(store().submit(make_job("2"), 2).kind, SubmitOutcome::Kind::kCreated);
  const auto full = store().submit(make_job("3"), 2);
  EXPECT_EQ(full.kind, SubmitOutcome::Kind::kQueueFull);
  EXPECT_FALSE(full.job);
  EXPECT_EQ(store().count_by_state()[JobState::kQueued], 2);
  ASSERT_TRUE(store().claim_next(claim_as()));  // one leaves the queue
  EXPECT_EQ(store().submit(make_job("3"), 2).kind, SubmitOutcome::Kind::kCreated);
}

TEST_P(JobStoreContract, CancelQueuedRunningAndFinished) {
  const auto running = submit("1");
  const auto queued = submit("2");
  const auto claimed = store().claim_next(claim_as());
  ASSERT_EQ(claimed->job.id, running);
  EXPECT_EQ(store().renew_lease(claimed->lease, 1min), LeaseStatus::kHeld);

  const auto q = store().cancel(queued);
  EXPECT_EQ(q.kind, CancelOutcome::Kind::kCancelled);
  EXPECT_EQ(q.job->state, JobState::kCancelled);
  EXPECT_TRUE(q.job->finished_at_ms);

  const auto r = store().cancel(running);
  EXPECT_EQ(r.kind, CancelOutcome::Kind::kRequested);
  EXPECT_EQ(r.job->state, JobState::kRunning);
  EXPECT_TRUE(r.job->cancel_requested);
  // The worker hears of it through its heartbeat, from whichever process took the cancel.
  EXPECT_EQ(store().renew_lease(claimed->lease, 1min), LeaseStatus::kCancelRequested);
  EXPECT_TRUE(store().complete_cancelled(claimed->lease));
  EXPECT_EQ(store().renew_lease(claimed->lease, 1min), LeaseStatus::kLost);

  EXPECT_EQ(store().cancel(running).kind, CancelOutcome::Kind::kAlreadyFinished);
  EXPECT_EQ(store().cancel(999).kind, CancelOutcome::Kind::kNotFound);
  EXPECT_FALSE(store().claim_next(claim_as()));  // a cancelled queued job is never claimed
}

TEST_P(JobStoreContract, DeleteOnlyFinishedJobsAndTheirResults) {
  const auto id = submit("1");
  EXPECT_EQ(store().remove(id), DeleteOutcome::kNotFinished);
  const Lease lease = store().claim_next(claim_as())->lease;
  EXPECT_EQ(store().remove(id), DeleteOutcome::kNotFinished);
  ASSERT_TRUE(store().complete_succeeded(lease, "{}", "vtu"));
  EXPECT_EQ(store().remove(id), DeleteOutcome::kDeleted);
  EXPECT_EQ(store().remove(id), DeleteOutcome::kNotFound);
  EXPECT_FALSE(store().find(id));
  EXPECT_FALSE(store().result_json(id));  // removed with the job (foreign key cascade)
  // Ids are never reused after a deletion.
  EXPECT_GT(submit("2"), id);
}

TEST_P(JobStoreContract, ListsNewestFirstWithKeysetPages) {
  std::vector<std::int64_t> ids;
  for (int i = 0; i < 7; ++i) ids.push_back(submit(std::to_string(i)));
  ASSERT_TRUE(store().claim_next(claim_as()));  // ids[0] is running

  JobListQuery query;
  query.page_size = 3;
  std::vector<std::int64_t> seen;
  int pages = 0;
  for (;;) {
    JobPage page = store().list(query);
    ++pages;
    for (const Job& j : page.jobs) seen.push_back(j.id);
    if (!page.next_before_id) break;
    query.before_id = page.next_before_id;
    // Jobs added while paging come before the first page, never into the walk.
    submit("late-" + std::to_string(pages));
  }
  EXPECT_EQ(pages, 3);
  EXPECT_EQ(seen, std::vector<std::int64_t>(ids.rbegin(), ids.rend()));

  JobListQuery running;
  running.state = JobState::kRunning;
  JobPage page = store().list(running);
  ASSERT_EQ(page.jobs.size(), 1u);
  EXPECT_EQ(page.jobs[0].id, ids[0]);
  EXPECT_FALSE(page.next_before_id);

  JobListQuery queued_before;  // both filters at once
  queued_before.state = JobState::kQueued;
  queued_before.before_id = ids[4];
  queued_before.page_size = 2;
  page = store().list(queued_before);
  ASSERT_EQ(page.jobs.size(), 2u);
  EXPECT_EQ(page.jobs[0].id, ids[3]);
  EXPECT_EQ(page.jobs[1].id, ids[2]);
  EXPECT_EQ(page.next_before_id, ids[2]);
  queued_before.before_id = page.next_before_id;
  page = store().list(queued_before);
  ASSERT_EQ(page.jobs.size(), 1u);  // ids[0] is running, not queued
  EXPECT_EQ(page.jobs[0].id, ids[1]);
  EXPECT_FALSE(page.next_before_id);

  JobListQuery exact;
  exact.page_size = 9;  // exactly all (7 + 2 added while paging): no further page
  EXPECT_EQ(store().list(exact).jobs.size(), 9u);
  EXPECT_FALSE(store().list(exact).next_before_id);
}

INSTANTIATE_TEST_SUITE_P(Stores, JobStoreContract, ::testing::Values("sqlite", "postgresql"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace fosls::service::testing
