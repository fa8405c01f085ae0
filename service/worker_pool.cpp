#include "worker_pool.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <optional>
#include <random>
#include <string>

namespace fosls::service {

std::string make_worker_id() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) std::snprintf(host, sizeof host, "unknown");
  std::random_device random;
  char suffix[16];
  std::snprintf(suffix, sizeof suffix, "%08x", static_cast<unsigned>(random()));
  return std::string(host) + ":" + std::to_string(getpid()) + ":" + suffix;
}

WorkerPool::WorkerPool(JobStore& store, JobRunner runner, EventLog& log, Metrics& metrics,
                       WorkerPoolOptions options)
    : store_(store), runner_(std::move(runner)), log_(log), metrics_(metrics), options_(options) {
  if (options_.workers < 0) options_.workers = 0;
  if (options_.worker_id.empty()) options_.worker_id = make_worker_id();
}

WorkerPool::~WorkerPool() {
  begin_shutdown();
  join();
}

void WorkerPool::start() {
  std::lock_guard lock(mutex_);
  if (!threads_.empty() || stopping_) return;
  if (options_.workers > 0) declare_budget();  // before the first claim
  for (int i = 0; i < options_.workers; ++i) threads_.emplace_back([this, i] { run_worker(i); });
  if (options_.workers > 0) heartbeat_ = std::thread([this] { run_heartbeat(); });
}

void WorkerPool::notify_job_available() {
  {
    std::lock_guard lock(mutex_);
    ++generation_;
  }
  wake_.notify_all();
}

void WorkerPool::request_cancel(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  auto it = active_.find(job_id);
  if (it == active_.end()) {
    // Claimed but not yet registered by its worker: it picks this up when it registers.
    early_cancels_.insert(job_id);
    return;
  }
  it->second.user_cancel = true;
  it->second.cancel->store(true);
}

void WorkerPool::begin_shutdown() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    for (auto& [id, job] : active_) job.cancel->store(true);
  }
  wake_.notify_all();
}

void WorkerPool::join() {
  for (auto& t : threads_) {
    if (t.joinable()) t.join();
  }
  threads_.clear();
  // Leases stay renewed until the last worker has put its job back.
  {
    std::lock_guard lock(mutex_);
    heartbeat_stopping_ = true;
  }
  wake_.notify_all();
  if (heartbeat_.joinable()) heartbeat_.join();
}

void WorkerPool::run_heartbeat() {
  auto declared = std::chrono::steady_clock::now();
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait_for(lock, options_.heartbeat_interval, [&] { return heartbeat_stopping_; });
      if (heartbeat_stopping_) return;
    }
    heartbeat_once();
    if (std::chrono::steady_clock::now() - declared >= options_.declare_interval) {
      declare_budget();
      declared = std::chrono::steady_clock::now();
    }
  }
}

void WorkerPool::declare_budget() {
  if (options_.declared_job_memory == 0) return;
  try {
    store_.declare_worker_budget(options_.worker_id, options_.declared_job_memory);
  } catch (const std::exception& e) {
    log_.write("store_error", {{"step", "declare budget"}, {"error", e.what()}});
  }
}

void WorkerPool::heartbeat_once() {
  std::vector<Lease> leases;
  {
    std::lock_guard lock(mutex_);
    for (const auto& [id, job] : active_) leases.push_back(job.lease);
  }
  for (const Lease& lease : leases) {
    LeaseStatus status = LeaseStatus::kHeld;
    try {
      status = store_.renew_lease(lease, options_.lease_duration);
    } catch (const std::exception& e) {
      // The lease lasts lease_duration: a store away for a few heartbeats costs nothing.
      log_.write("store_error",
                 {{"job_id", lease.job_id}, {"step", "heartbeat"}, {"error", e.what()}});
      continue;
    }
    if (status == LeaseStatus::kHeld) continue;
    std::lock_guard lock(mutex_);
    auto it = active_.find(lease.job_id);
    if (it == active_.end() || it->second.lease.attempt != lease.attempt) continue;
    if (status == LeaseStatus::kCancelRequested) {
      it->second.user_cancel = true;
    } else {
      it->second.lease_lost = true;
      log_.write("lease_lost", {{"job_id", lease.job_id}, {"attempt", lease.attempt}});
    }
    it->second.cancel->store(true);
  }
}

void WorkerPool::run_worker(int index) {
  // Share the cores between the workers: a solve in each of N workers with all cores each
  // would oversubscribe the machine, and OpenMP's barriers then wait on descheduled threads.
  omp_set_num_threads(std::max(1, omp_get_num_procs() / std::max(1, options_.workers)));
  for (;;) {
    std::uint64_t seen = 0;
    {
      std::lock_guard lock(mutex_);
      if (stopping_) return;
      seen = generation_;
    }
    std::optional<ClaimedJob> claimed;
    try {
      claimed = store_.claim_next(
          ClaimRequest{options_.worker_id + "/w" + std::to_string(index), options_.lease_duration});
    } catch (const std::exception& e) {
      log_.write("worker_error", {{"worker", index}, {"step", "claim"}, {"error", e.what()}});
    }
    if (claimed) {
      run_job(*claimed);
      continue;
    }
    std::unique_lock lock(mutex_);
    wake_.wait_for(lock, options_.idle_poll, [&] { return stopping_ || generation_ != seen; });
  }
}

std::string WorkerPool::unconverged_error(const JobConvergence& convergence) {
  return "the solve stopped without converging (stop_reason " +
         (convergence.stop_reason.empty() ? std::string("unknown") : convergence.stop_reason) +
         ") and this service fails such jobs (--fail-unconverged); the result is kept at "
         "links.result: its message and warnings say what to change";
}

bool WorkerPool::with_retries(const char* what, std::int64_t job_id,
                              const std::function<bool()>& write, std::string& error) {
  auto delay = options_.store_retry_delay;
  for (int attempt = 1;; ++attempt) {
    try {
      return write();
    } catch (const std::exception& e) {
      error = e.what();
      log_.write("store_error",
                 {{"job_id", job_id}, {"step", what}, {"try", attempt}, {"error", e.what()}});
      if (attempt == 5) return false;
    }
    std::this_thread::sleep_for(delay);
    delay *= 2;
  }
}

namespace {

/// The progress reports of one run, written to the store at most every `interval` (the solver
/// may iterate thousands of times a second); the last one is written when the run ends.
class ProgressWriter {
 public:
  ProgressWriter(JobStore& store, const Lease& lease, EventLog& log,
                 std::chrono::milliseconds interval)
      : store_(store), lease_(lease), log_(log), interval_(interval) {}

  void report(const JobProgress& progress) {
    last_ = progress;
    const auto now = Clock::now();
    if (written_ && now - *written_ < interval_) return;
    written_ = now;
    try {
      store_.update_progress(lease_, progress);
    } catch (const std::exception& e) {
      // Progress is advisory; a busy store must not fail the solve.
      log_.write("store_error",
                 {{"job_id", lease_.job_id}, {"step", "progress"}, {"error", e.what()}});
    }
  }

  /// The last report, if the throttle held it back; best effort: the final state matters, the
  /// last progress figure does not.
  void flush() {
    if (!last_) return;
    try {
      store_.update_progress(lease_, *last_);
    } catch (const std::exception&) {
    }
  }

 private:
  using Clock = std::chrono::steady_clock;
  JobStore& store_;
  const Lease& lease_;
  EventLog& log_;
  std::chrono::milliseconds interval_;
  std::optional<Clock::time_point> written_;
  std::optional<JobProgress> last_;
};

}  // namespace

void WorkerPool::run_job(const ClaimedJob& claimed) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point started = Clock::now();
  const auto cancel = register_job(claimed);
  ProgressWriter progress(store_, claimed.lease, log_, options_.progress_interval);
  JobRunContext context{*cancel, [&](const JobProgress& p) { progress.report(p); },
                        claimed.time_estimate_seconds};
  JobRunOutcome outcome = solve(claimed, context);
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();

  const RunEnd end = unregister_job(claimed.job.id);
  if (end.lease_lost) {
    // Another worker has (or had) this job now; whatever this run produced is not stored.
    --busy_;
    log_.write("job_transition", {{"job_id", claimed.job.id},
                                  {"from", "running"},
                                  {"to", "abandoned"},
                                  {"attempt", claimed.lease.attempt},
                                  {"seconds", seconds},
                                  {"stored", false},
                                  {"reason", "lease lost"}});
    return;
  }
  progress.flush();
  const nlohmann::json transition = record_outcome(claimed.lease, outcome, end, seconds);
  --busy_;
  log_.write("job_transition", transition);
}

std::shared_ptr<std::atomic<bool>> WorkerPool::register_job(const ClaimedJob& claimed) {
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  {
    std::lock_guard lock(mutex_);
    ActiveJob active{claimed.lease, cancel, early_cancels_.erase(claimed.job.id) > 0};
    if (active.user_cancel || stopping_) cancel->store(true);
    active_.emplace(claimed.job.id, active);
  }
  ++busy_;
  log_.write("job_transition", {{"job_id", claimed.job.id},
                                {"from", "queued"},
                                {"to", "running"},
                                {"attempt", claimed.lease.attempt}});
  return cancel;
}

JobRunOutcome WorkerPool::solve(const ClaimedJob& claimed, const JobRunContext& context) {
  JobRunOutcome outcome;
  try {
    outcome = runner_(nlohmann::json::parse(claimed.case_json), context);
  } catch (const std::exception& e) {
    outcome.kind = JobRunOutcome::Kind::kFailed;
    outcome.error = std::string("internal error while solving: ") + e.what();
  } catch (const std::string& e) {  // gmsh throws std::string
    outcome.kind = JobRunOutcome::Kind::kFailed;
    outcome.error = "internal error while solving: " + e;
  } catch (...) {
    outcome.kind = JobRunOutcome::Kind::kFailed;
    outcome.error = "internal error while solving (unknown exception)";
  }
  return outcome;
}

WorkerPool::RunEnd WorkerPool::unregister_job(std::int64_t job_id) {
  std::lock_guard lock(mutex_);
  const ActiveJob& active = active_[job_id];
  const RunEnd end{active.user_cancel, active.lease_lost, stopping_};
  active_.erase(job_id);
  return end;
}

nlohmann::json WorkerPool::record_outcome(const Lease& lease, JobRunOutcome& outcome,
                                          const RunEnd& end, double seconds) {
  nlohmann::json fields = {{"job_id", lease.job_id},
                           {"from", "running"},
                           {"attempt", lease.attempt},
                           {"seconds", seconds}};
  bool stored = false;
  std::string store_error;
  if (outcome.kind == JobRunOutcome::Kind::kSucceeded) {
    stored = store_result(lease, outcome, seconds, fields);
  } else if (outcome.kind == JobRunOutcome::Kind::kCancelled && end.stopping && !end.user_cancel) {
    // Interrupted by shutdown, not by its user: nothing is lost, it runs again next start.
    fields["to"] = "queued";
    stored = with_retries(
        "requeue", lease.job_id, [&] { return store_.requeue(lease); }, store_error);
  } else if (outcome.kind == JobRunOutcome::Kind::kCancelled && !outcome.result_json.empty()) {
    stored = store_result(lease, outcome, seconds, fields);  // the load steps solved before it
  } else if (outcome.kind == JobRunOutcome::Kind::kCancelled) {
    fields["to"] = "cancelled";
    stored = with_retries(
        "store cancel", lease.job_id, [&] { return store_.complete_cancelled(lease); },
        store_error);
    metrics_.record_run(JobState::kCancelled, seconds);
  }
  if (outcome.kind == JobRunOutcome::Kind::kFailed) {
    fields["to"] = "failed";
    fields["error"] = outcome.error;
    stored = with_retries(
        "store failure", lease.job_id, [&] { return store_.complete_failed(lease, outcome.error); },
        store_error);
    metrics_.record_run(JobState::kFailed, seconds);
  }
  fields["stored"] = stored;
  return fields;
}

bool WorkerPool::store_result(const Lease& lease, JobRunOutcome& outcome, double seconds,
                              nlohmann::json& fields) {
  SolveRecord record;
  record.convergence = convergence_of_result(outcome.result_json);
  record.result_json = std::move(outcome.result_json);
  record.vtu = std::move(outcome.vtu);
  record.cancelled = outcome.kind == JobRunOutcome::Kind::kCancelled;
  if (options_.fail_unconverged && record.convergence.converged == false && !record.cancelled)
    record.error = unconverged_error(record.convergence);
  const JobState state = record.cancelled       ? JobState::kCancelled
                         : record.error.empty() ? JobState::kSucceeded
                                                : JobState::kFailed;
  fields["to"] = to_string(state);
  if (record.convergence.converged) {
    fields["converged"] = *record.convergence.converged;
    fields["stop_reason"] = record.convergence.stop_reason;
  }
  std::string store_error;
  const bool stored = with_retries(
      "store result", lease.job_id, [&] { return store_.complete_with_result(lease, record); },
      store_error);
  if (!stored && !store_error.empty()) {
    // For example a VTU beyond SQLite's size limit: say so rather than stay "running".
    outcome.kind = JobRunOutcome::Kind::kFailed;
    outcome.error = "the solve finished but its result could not be stored: " + store_error;
    return false;
  }
  metrics_.record_run(state, seconds);
  metrics_.record_stop_reason(record.convergence.stop_reason);
  if (state == JobState::kFailed) fields["error"] = record.error;
  return stored;
}

}  // namespace fosls::service
