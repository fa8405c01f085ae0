// The SQLite job store: lifecycle, idempotency, pagination, recovery, retention, and many
// threads at once without "database is locked".

#include "sqlite_job_store.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <atomic>
#include <set>
#include <thread>
#include <vector>

#include "request_checks.hpp"
#include "temp_dir.hpp"

namespace fosls::service {
namespace {

using testing::TempDir;

NewJob make_job(const std::string& body, std::optional<std::string> key = std::nullopt) {
  NewJob job;
  job.name = "case";
  job.case_json = body;
  job.body_hash = sha256_hex(body);
  job.idempotency_key = std::move(key);
  return job;
}

constexpr std::size_t kUnlimited = 1'000'000;

TEST(SqliteJobStore, SubmitClaimSucceedStoresResultOnce) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  const SubmitOutcome submitted = store.submit(make_job(R"({"a":1})"), kUnlimited);
  ASSERT_EQ(submitted.kind, SubmitOutcome::Kind::kCreated);
  const std::int64_t id = submitted.job->id;
  EXPECT_EQ(submitted.job->state, JobState::kQueued);
  EXPECT_EQ(submitted.job->attempts, 0);

  auto claimed = store.claim_next();
  ASSERT_TRUE(claimed);
  EXPECT_EQ(claimed->job.id, id);
  EXPECT_EQ(claimed->job.state, JobState::kRunning);
  EXPECT_EQ(claimed->job.attempts, 1);
  EXPECT_TRUE(claimed->job.started_at_ms);
  EXPECT_EQ(claimed->case_json, R"({"a":1})");
  EXPECT_FALSE(store.claim_next());  // nothing else queued

  store.update_progress(id, 1, JobProgress{7, 1e-3, -2.5});
  auto running = store.find(id);
  ASSERT_TRUE(running && running->progress);
  EXPECT_EQ(running->progress->iteration, 7);
  EXPECT_DOUBLE_EQ(running->progress->kkt_residual, 1e-3);

  EXPECT_TRUE(store.complete_succeeded(id, 1, R"({"converged":true})", "<VTKFile/>"));
  // A second completion of the same attempt is refused: a result is written once.
  EXPECT_FALSE(store.complete_succeeded(id, 1, R"({"converged":false})", ""));
  EXPECT_FALSE(store.complete_failed(id, 1, "late"));
  auto done = store.find(id);
  EXPECT_EQ(done->state, JobState::kSucceeded);
  EXPECT_TRUE(done->finished_at_ms);
  EXPECT_EQ(store.result_json(id), R"({"converged":true})");
  EXPECT_EQ(store.vtu(id), "<VTKFile/>");
}

TEST(SqliteJobStore, ProgressOfAStaleAttemptIsIgnored) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  const auto id = store.submit(make_job("{}"), kUnlimited).job->id;
  ASSERT_TRUE(store.claim_next());
  store.update_progress(id, 2, JobProgress{3, 1, 1});  // wrong attempt
  EXPECT_FALSE(store.find(id)->progress);
}

TEST(SqliteJobStore, FailedJobKeepsItsError) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  const auto id = store.submit(make_job("{}"), kUnlimited).job->id;
  ASSERT_TRUE(store.claim_next());
  EXPECT_TRUE(store.complete_failed(id, 1, "/weights/c1: must be positive"));
  auto job = store.find(id);
  EXPECT_EQ(job->state, JobState::kFailed);
  EXPECT_EQ(job->error, "/weights/c1: must be positive");
  EXPECT_FALSE(store.result_json(id));
}

TEST(SqliteJobStore, ClaimsOldestFirst) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  const auto first = store.submit(make_job("1"), kUnlimited).job->id;
  const auto second = store.submit(make_job("2"), kUnlimited).job->id;
  EXPECT_EQ(store.claim_next()->job.id, first);
  EXPECT_EQ(store.claim_next()->job.id, second);
}

TEST(SqliteJobStore, IdempotencyKeyReplaysSameBodyAndRejectsDifferentBody) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  const auto created = store.submit(make_job(R"({"x":1})", "key-1"), kUnlimited);
  ASSERT_EQ(created.kind, SubmitOutcome::Kind::kCreated);
  const auto replay = store.submit(make_job(R"({"x":1})", "key-1"), kUnlimited);
  EXPECT_EQ(replay.kind, SubmitOutcome::Kind::kReplayed);
  EXPECT_EQ(replay.job->id, created.job->id);
  const auto conflict = store.submit(make_job(R"({"x":2})", "key-1"), kUnlimited);
  EXPECT_EQ(conflict.kind, SubmitOutcome::Kind::kKeyConflict);
  EXPECT_EQ(conflict.job->id, created.job->id);
  const auto other = store.submit(make_job(R"({"x":1})", "key-2"), kUnlimited);
  EXPECT_EQ(other.kind, SubmitOutcome::Kind::kCreated);
  EXPECT_NE(other.job->id, created.job->id);
  EXPECT_EQ(store.count_by_state()[JobState::kQueued], 2);
}

TEST(SqliteJobStore, QueueLimitCountsOnlyQueuedJobs) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  EXPECT_EQ(store.submit(make_job("1"), 2).kind, SubmitOutcome::Kind::kCreated);
  EXPECT_EQ(store.submit(make_job("2"), 2).kind, SubmitOutcome::Kind::kCreated);
  const auto full = store.submit(make_job("3"), 2);
  EXPECT_EQ(full.kind, SubmitOutcome::Kind::kQueueFull);
  EXPECT_FALSE(full.job);
  EXPECT_EQ(store.count_by_state()[JobState::kQueued], 2);
  ASSERT_TRUE(store.claim_next());  // one leaves the queue
  EXPECT_EQ(store.submit(make_job("3"), 2).kind, SubmitOutcome::Kind::kCreated);
}

TEST(SqliteJobStore, CancelQueuedRunningAndFinished) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  const auto running = store.submit(make_job("1"), kUnlimited).job->id;
  const auto queued = store.submit(make_job("2"), kUnlimited).job->id;
  ASSERT_EQ(store.claim_next()->job.id, running);

  const auto q = store.cancel(queued);
  EXPECT_EQ(q.kind, CancelOutcome::Kind::kCancelled);
  EXPECT_EQ(q.job->state, JobState::kCancelled);
  EXPECT_TRUE(q.job->finished_at_ms);

  const auto r = store.cancel(running);
  EXPECT_EQ(r.kind, CancelOutcome::Kind::kRequested);
  EXPECT_EQ(r.job->state, JobState::kRunning);
  EXPECT_TRUE(r.job->cancel_requested);
  EXPECT_TRUE(store.complete_cancelled(running, 1));

  EXPECT_EQ(store.cancel(running).kind, CancelOutcome::Kind::kAlreadyFinished);
  EXPECT_EQ(store.cancel(999).kind, CancelOutcome::Kind::kNotFound);
  EXPECT_FALSE(store.claim_next());  // a cancelled queued job is never claimed
}

TEST(SqliteJobStore, DeleteOnlyFinishedJobsAndTheirResults) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  const auto id = store.submit(make_job("1"), kUnlimited).job->id;
  EXPECT_EQ(store.remove(id), DeleteOutcome::kNotFinished);
  ASSERT_TRUE(store.claim_next());
  EXPECT_EQ(store.remove(id), DeleteOutcome::kNotFinished);
  ASSERT_TRUE(store.complete_succeeded(id, 1, "{}", "vtu"));
  EXPECT_EQ(store.remove(id), DeleteOutcome::kDeleted);
  EXPECT_EQ(store.remove(id), DeleteOutcome::kNotFound);
  EXPECT_FALSE(store.find(id));
  EXPECT_FALSE(store.result_json(id));  // removed with the job (foreign key cascade)
  // Ids are never reused after a deletion.
  EXPECT_GT(store.submit(make_job("2"), kUnlimited).job->id, id);
}

TEST(SqliteJobStore, ListsNewestFirstWithKeysetPages) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  std::vector<std::int64_t> ids;
  for (int i = 0; i < 7; ++i) {
    ids.push_back(store.submit(make_job(std::to_string(i)), kUnlimited).job->id);
  }
  ASSERT_TRUE(store.claim_next());  // ids[0] is running

  JobListQuery query;
  query.page_size = 3;
  std::vector<std::int64_t> seen;
  int pages = 0;
  for (;;) {
    JobPage page = store.list(query);
    ++pages;
    for (const Job& j : page.jobs) seen.push_back(j.id);
    if (!page.next_before_id) break;
    query.before_id = page.next_before_id;
  }
  EXPECT_EQ(pages, 3);
  EXPECT_EQ(seen, std::vector<std::int64_t>(ids.rbegin(), ids.rend()));

  JobListQuery running;
  running.state = JobState::kRunning;
  JobPage page = store.list(running);
  ASSERT_EQ(page.jobs.size(), 1u);
  EXPECT_EQ(page.jobs[0].id, ids[0]);
  EXPECT_FALSE(page.next_before_id);

  JobListQuery exact;
  exact.page_size = 7;  // exactly all: no further page
  EXPECT_FALSE(store.list(exact).next_before_id);
}

TEST(SqliteJobStore, RecoveryRequeuesThenFailsAtMaxAttemptsAndHonoursCancels) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  std::int64_t a = 0, b = 0, c = 0;
  {
    SqliteJobStore store(path);
    a = store.submit(make_job("1"), kUnlimited).job->id;
    b = store.submit(make_job("2"), kUnlimited).job->id;
    c = store.submit(make_job("3"), kUnlimited).job->id;
    ASSERT_EQ(store.claim_next()->job.id, a);
    ASSERT_EQ(store.claim_next()->job.id, b);
    ASSERT_EQ(store.cancel(b).kind, CancelOutcome::Kind::kRequested);
    // The process "crashes" here: the store goes away with a and b running.
  }
  {
    SqliteJobStore store(path);
    const RecoveryReport report = store.recover_interrupted(2);
    EXPECT_EQ(report.requeued, std::vector<std::int64_t>{a});
    EXPECT_EQ(report.cancelled, std::vector<std::int64_t>{b});
    EXPECT_TRUE(report.failed.empty());
    EXPECT_EQ(store.find(b)->state, JobState::kCancelled);
    EXPECT_EQ(store.find(c)->state, JobState::kQueued);
    auto again = store.claim_next();
    ASSERT_EQ(again->job.id, a);
    EXPECT_EQ(again->job.attempts, 2);
    // ... and crashes again while solving a.
  }
  SqliteJobStore store(path);
  const RecoveryReport report = store.recover_interrupted(2);
  EXPECT_EQ(report.failed, std::vector<std::int64_t>{a});
  EXPECT_TRUE(report.requeued.empty());
  EXPECT_EQ(store.find(a)->state, JobState::kFailed);
  EXPECT_NE(store.find(a)->error.find("max-attempts"), std::string::npos);
  EXPECT_EQ(store.find(c)->state, JobState::kQueued);  // never started: untouched
}

TEST(SqliteJobStore, RecoveryBelowLimitRequeuesAndCountsTheAttempt) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  std::int64_t id = 0;
  {
    SqliteJobStore store(path);
    id = store.submit(make_job("1"), kUnlimited).job->id;
    ASSERT_TRUE(store.claim_next());
    store.update_progress(id, 1, JobProgress{5, 0.1, 0.2});
  }
  SqliteJobStore store(path);
  const RecoveryReport report = store.recover_interrupted(3);
  EXPECT_EQ(report.requeued, std::vector<std::int64_t>{id});
  auto job = store.find(id);
  EXPECT_EQ(job->state, JobState::kQueued);
  EXPECT_EQ(job->attempts, 1);
  EXPECT_FALSE(job->progress);
  EXPECT_FALSE(job->started_at_ms);
  auto claimed = store.claim_next();
  ASSERT_TRUE(claimed);
  EXPECT_EQ(claimed->job.attempts, 2);
  // The interrupted attempt can no longer complete the job.
  EXPECT_FALSE(store.complete_succeeded(id, 1, "{}", ""));
  EXPECT_TRUE(store.complete_succeeded(id, 2, "{}", ""));
}

TEST(SqliteJobStore, RequeueAfterCancelRequestCancels) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  const auto id = store.submit(make_job("1"), kUnlimited).job->id;
  ASSERT_TRUE(store.claim_next());
  ASSERT_EQ(store.cancel(id).kind, CancelOutcome::Kind::kRequested);
  EXPECT_TRUE(store.requeue(id, 1));
  EXPECT_EQ(store.find(id)->state, JobState::kCancelled);
}

TEST(SqliteJobStore, RetentionDeletesOnlyOldFinishedJobs) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  const auto finished = store.submit(make_job("1"), kUnlimited).job->id;
  const auto queued = store.submit(make_job("2"), kUnlimited).job->id;
  ASSERT_TRUE(store.claim_next());
  ASSERT_TRUE(store.complete_succeeded(finished, 1, "{}", ""));
  const std::int64_t finished_at = *store.find(finished)->finished_at_ms;
  EXPECT_EQ(store.delete_finished_before(finished_at), 0);  // not older than the cut-off
  EXPECT_EQ(store.delete_finished_before(finished_at + 1), 1);
  EXPECT_FALSE(store.find(finished));
  EXPECT_TRUE(store.find(queued));  // unfinished jobs are never deleted
  EXPECT_EQ(store.delete_finished_before(now_unix_ms() + 1'000'000), 0);
}

TEST(SqliteJobStore, DatabaseIsInWalMode) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  SqliteJobStore store(path);
  store.submit(make_job("1"), kUnlimited);
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "PRAGMA journal_mode", -1, &stmt, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(stmt), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0)), "wal");
  sqlite3_finalize(stmt);
  sqlite3_close(db);
}

TEST(SqliteJobStore, SchemaFromANewerProgramIsRefused) {
  TempDir dir;
  const std::string path = dir.file("jobs.db");
  { SqliteJobStore store(path); }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "PRAGMA user_version = 99", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  EXPECT_THROW(SqliteJobStore store(path), StoreError);
}

TEST(SqliteJobStore, UnwritableLocationIsAStoreError) {
  EXPECT_THROW(SqliteJobStore store("/proc/no/such/folder/jobs.db"), StoreError);
}

// Submitters, claimers and readers on separate threads (each with its own connection): every
// job is claimed exactly once and no call fails with "database is locked".
TEST(SqliteJobStore, ManyThreadsSubmitClaimAndCompleteWithoutLockErrors) {
  TempDir dir;
  SqliteJobStore store(dir.file("jobs.db"));
  constexpr int kSubmitters = 4;
  constexpr int kPerSubmitter = 50;
  constexpr int kWorkers = 3;
  std::atomic<int> errors{0};
  std::atomic<int> completed{0};
  std::mutex claimed_mutex;
  std::multiset<std::int64_t> claimed_ids;

  std::vector<std::thread> threads;
  for (int s = 0; s < kSubmitters; ++s) {
    threads.emplace_back([&, s] {
      for (int i = 0; i < kPerSubmitter; ++i) {
        try {
          const std::string key = "k" + std::to_string(s) + "-" + std::to_string(i);
          auto out = store.submit(make_job(std::to_string(i), key), kUnlimited);
          if (out.kind != SubmitOutcome::Kind::kCreated) ++errors;
          // Every request is retried once, as a client would after a timeout.
          if (store.submit(make_job(std::to_string(i), key), kUnlimited).kind !=
              SubmitOutcome::Kind::kReplayed) {
            ++errors;
          }
          store.find(out.job->id);
        } catch (const StoreError&) {
          ++errors;
        }
      }
    });
  }
  for (int w = 0; w < kWorkers; ++w) {
    threads.emplace_back([&] {
      while (completed.load() < kSubmitters * kPerSubmitter) {
        try {
          auto job = store.claim_next();
          if (!job) {
            std::this_thread::yield();
            continue;
          }
          {
            std::lock_guard lock(claimed_mutex);
            claimed_ids.insert(job->job.id);
          }
          store.update_progress(job->job.id, job->job.attempts, JobProgress{1, 0.5, 0.5});
          if (!store.complete_succeeded(job->job.id, job->job.attempts, "{}", "")) ++errors;
          ++completed;
        } catch (const StoreError&) {
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
  EXPECT_EQ(store.count_by_state()[JobState::kSucceeded], kSubmitters * kPerSubmitter);
}

}  // namespace
}  // namespace fosls::service
