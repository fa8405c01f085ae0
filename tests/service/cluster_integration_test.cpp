// Several processes on one PostgreSQL database, through the real programs: one API-only
// fosls-serve and several fosls-worker, on a throwaway server this test starts itself.
//
// Crashes: jobs posted from 8 parallel clients while one worker at a time is killed with
// SIGKILL (and restarted) five times and the API process once: every job ends succeeded, with
// exactly one stored result, none lost; the attempts per job are printed.
//
//   build/bin/cluster_integration_test --gtest_filter='*Crash*'   # FOSLS_CLUSTER_JOBS=300
//
// Throughput (a measurement, not a test; docs/service.md): jobs per minute of a small case
// with 1, 2 and 4 worker processes.
//
//   build/bin/cluster_integration_test --gtest_also_run_disabled_tests
//   --gtest_filter='*Throughput*'

#include <gtest/gtest.h>
#include <httplib.h>
#include <libpq-fe.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include "postgres_cluster.hpp"
#include "postgres_job_store.hpp"
#include "request_checks.hpp"
#include "temp_dir.hpp"

namespace fosls::service {
namespace {

using nlohmann::json;
using testing::PostgresCluster;
using testing::spawn;
using testing::TempDir;
using Clock = std::chrono::steady_clock;

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : fallback;
}

json small_case(int tag) {
  std::ifstream in(std::string(FOSLS_EXAMPLES_DIR) + "/signorini_square.json");
  std::stringstream ss;
  ss << in.rdbuf();
  json j = json::parse(ss.str());
  j["name"] = "cluster-" + std::to_string(tag);
  // 520 unknowns (a fraction of a second) unless FOSLS_CLUSTER_REFINEMENTS says otherwise.
  j["mesh"]["refinements"] = env_int("FOSLS_CLUSTER_REFINEMENTS", 1);
  return j;
}

/// Rows of a query on the test database, as text.
std::vector<std::vector<std::string>> sql_rows(const std::string& url, const std::string& sql) {
  std::vector<std::vector<std::string>> rows;
  PGconn* c = PQconnectdb(url.c_str());
  PGresult* r = PQexec(c, sql.c_str());
  if (PQresultStatus(r) != PGRES_TUPLES_OK) {
    ADD_FAILURE() << sql << ": " << PQerrorMessage(c);
  } else {
    for (int i = 0; i < PQntuples(r); ++i) {
      std::vector<std::string> row;
      for (int k = 0; k < PQnfields(r); ++k) row.emplace_back(PQgetvalue(r, i, k));
      rows.push_back(std::move(row));
    }
  }
  PQclear(r);
  PQfinish(c);
  return rows;
}

long long sql_count(const std::string& url, const std::string& sql) {
  const auto rows = sql_rows(url, sql);
  return rows.empty() ? -1 : std::stoll(rows[0][0]);
}

/// One program of the cluster: started, killed, restarted; stopped (SIGTERM) at the end.
class Program {
 public:
  Program(std::vector<std::string> args, std::string log) : args_(std::move(args)), log_(log) {}
  ~Program() { stop(); }
  void start() { pid_ = spawn(args_, log_, /*die_with_parent=*/true); }
  void kill_hard() { signal_and_wait(SIGKILL); }
  /// SIGTERM and wait: running jobs go back to the queue.
  void stop() { signal_and_wait(SIGTERM); }
  const std::string& log_path() const { return log_; }
  pid_t pid() const { return pid_; }
  /// CPU time (user + system, all threads) the running program has used so far.
  double cpu_seconds() const {
    std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Fields after the command name (which is in parentheses and may hold spaces): utime and
    // stime are fields 14 and 15 of the line, 12th and 13th after the ')'.
    std::istringstream rest(text.substr(text.rfind(')') + 2));
    std::string field;
    double ticks = 0;
    for (int i = 1; i <= 13 && rest >> field; ++i) {
      if (i >= 12) ticks += std::stod(field);
    }
    return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
  }

 private:
  void signal_and_wait(int sig) {
    if (pid_ <= 0) return;
    kill(pid_, sig);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
  }
  std::vector<std::string> args_;
  std::string log_;
  pid_t pid_ = -1;
};

/// A PostgreSQL server, one API-only fosls-serve on a fixed port and `workers` fosls-worker.
class Cluster {
 public:
  explicit Cluster(int workers, double lease_seconds = 2.0,
                   const std::vector<std::string>& worker_options = {}) {
    url_ = pg_.create_database("cluster");
    port_ = testing::free_port();
    const std::vector<std::string> lease = {"--lease-seconds", std::to_string(lease_seconds),
                                            "--heartbeat-seconds", "0.5"};
    std::vector<std::string> api = {FOSLS_SERVE_PATH,
                                    "--store",
                                    url_,
                                    "--workers",
                                    "0",
                                    "--host",
                                    "127.0.0.1",
                                    "--port",
                                    std::to_string(port_),
                                    "--web-root",
                                    dir_.path().string()};
    api.insert(api.end(), lease.begin(), lease.end());
    api_ = std::make_unique<Program>(api, dir_.file("api.log"));
    api_->start();
    for (int i = 0; i < workers; ++i) {
      std::vector<std::string> args = {FOSLS_WORKER_PATH, "--store", url_, "--workers", "1"};
      args.insert(args.end(), lease.begin(), lease.end());
      args.insert(args.end(), worker_options.begin(), worker_options.end());
      workers_.push_back(
          std::make_unique<Program>(args, dir_.file("worker" + std::to_string(i) + ".log")));
    }
    wait_healthy();
  }

  void start_workers() {
    for (auto& w : workers_) w->start();
  }
  /// CPU seconds used by the worker processes so far.
  double worker_cpu_seconds() const {
    double total = 0;
    for (const auto& w : workers_) total += w->cpu_seconds();
    return total;
  }
  Program& api() { return *api_; }
  Program& worker(int i) { return *workers_[static_cast<std::size_t>(i)]; }
  int port() const { return port_; }
  const std::string& url() const { return url_; }
  std::string log_dir() const { return dir_.path().string(); }

  /// Waits until the API answers /healthz.
  void wait_healthy() {
    const auto give_up = Clock::now() + std::chrono::seconds(60);
    while (Clock::now() < give_up) {
      httplib::Client cli("127.0.0.1", port_);
      auto res = cli.Get("/healthz");
      if (res && res->status == 200) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ADD_FAILURE() << "the API did not come up:\n" << testing::read_file(api_->log_path());
  }

  /// Waits until `n` jobs exist and none is queued or running; false after `seconds`.
  bool wait_all_finished(long long n, int seconds) {
    const auto give_up = Clock::now() + std::chrono::seconds(seconds);
    while (Clock::now() < give_up) {
      if (sql_count(url_,
                    "SELECT count(*) FROM jobs WHERE state IN ('succeeded', 'failed', "
                    "'cancelled')") >= n) {
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
  }

  /// Every log line of every program.
  std::string logs() const {
    std::string all = testing::read_file(api_->log_path());
    for (const auto& w : workers_) all += testing::read_file(w->log_path());
    return all;
  }

 private:
  PostgresCluster pg_;
  TempDir dir_;
  std::string url_;
  int port_ = 0;
  std::unique_ptr<Program> api_;
  std::vector<std::unique_ptr<Program>> workers_;
};

/// Posts jobs 0..n-1 from `clients` threads, each with its own Idempotency-Key, retrying a
/// job until it is accepted (the API may be down for a moment). Returns the ids by job number.
std::vector<std::int64_t> post_jobs(Cluster& cluster, int n, int clients) {
  std::vector<std::int64_t> ids(static_cast<std::size_t>(n), 0);
  std::atomic<int> next{0};
  std::vector<std::thread> threads;
  for (int c = 0; c < clients; ++c) {
    threads.emplace_back([&] {
      for (int i = next++; i < n; i = next++) {
        const httplib::Headers key = {{"Idempotency-Key", "cluster-job-" + std::to_string(i)}};
        const std::string body = small_case(i).dump();
        const auto give_up = Clock::now() + std::chrono::seconds(120);
        while (Clock::now() < give_up) {
          httplib::Client cli("127.0.0.1", cluster.port());
          cli.set_connection_timeout(std::chrono::seconds(2));
          auto res = cli.Post("/v1/jobs", key, body, "application/json");
          if (res && (res->status == 202 || res->status == 200)) {
            ids[static_cast<std::size_t>(i)] = json::parse(res->body)["id"].get<std::int64_t>();
            break;
          }
          std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
      }
    });
  }
  for (auto& t : threads) t.join();
  return ids;
}

TEST(Cluster, CrashesOfWorkersAndTheApiLoseNothingAndStoreNothingTwice) {
  const int n = env_int("FOSLS_CLUSTER_JOBS", 300);
  constexpr int kWorkers = 3;
  Cluster cluster(kWorkers);
  cluster.start_workers();
  const auto started = Clock::now();

  // The clients post in the background. Chaos runs on this thread, which outlives the test's
  // programs: a child dies with the thread that started it (PR_SET_PDEATHSIG).
  std::vector<std::int64_t> ids;
  std::thread posting([&] { ids = post_jobs(cluster, n, 8); });
  // Five SIGKILLs of a worker (restarted each time), one of the API (restarted on the same
  // port).
  std::vector<std::string> chaos_log;
  {
    for (int k = 0; k < 6; ++k) {
      // Spread over the run: the k-th event once (k+1)/8 of the jobs have succeeded.
      const auto wait_until = Clock::now() + std::chrono::seconds(60);
      while (sql_count(cluster.url(), "SELECT count(*) FROM jobs WHERE state = 'succeeded'") <
                 (k + 1) * n / 8 &&
             Clock::now() < wait_until) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
      if (k == 2) {
        cluster.api().kill_hard();
        chaos_log.push_back("SIGKILL api");
        cluster.api().start();
        cluster.wait_healthy();
        continue;
      }
      // Kill while it solves: its worker id (hostname:pid:…) holds a running job's lease.
      const int w = k % kWorkers;
      const std::string holds =
          "SELECT count(*) FROM jobs WHERE state = 'running' AND "
          "lease_owner LIKE '%:" +
          std::to_string(cluster.worker(w).pid()) + ":%'";
      const auto give_up = Clock::now() + std::chrono::seconds(10);
      while (sql_count(cluster.url(), holds) < 1 && Clock::now() < give_up) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      const bool busy = sql_count(cluster.url(), holds) > 0;
      cluster.worker(w).kill_hard();
      chaos_log.push_back("SIGKILL worker " + std::to_string(w) + (busy ? " solving" : " idle"));
      cluster.worker(w).start();
    }
  }
  posting.join();
  const bool finished = cluster.wait_all_finished(n, 240);
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  EXPECT_TRUE(finished) << cluster.logs();

  // Every job was accepted once: n distinct ids, n rows.
  EXPECT_EQ(std::set<std::int64_t>(ids.begin(), ids.end()).size(), static_cast<std::size_t>(n));
  EXPECT_EQ(std::count(ids.begin(), ids.end(), 0), 0) << "a job was never accepted";
  EXPECT_EQ(sql_count(cluster.url(), "SELECT count(*) FROM jobs"), n);
  // Every job succeeded, with exactly one result (job_id is the key of job_results).
  EXPECT_EQ(sql_count(cluster.url(), "SELECT count(*) FROM jobs WHERE state = 'succeeded'"), n);
  EXPECT_EQ(sql_count(cluster.url(),
                      "SELECT count(*) FROM job_results r JOIN jobs j ON "
                      "j.id = r.job_id WHERE j.state = 'succeeded'"),
            n);

  // The logs: one stored success per job; what late workers tried is refused, not stored.
  std::map<std::int64_t, int> stored_successes;
  int refused = 0, abandoned = 0;
  std::istringstream lines(cluster.logs());
  for (std::string line; std::getline(lines, line);) {
    const json j = json::parse(line, nullptr, false);
    if (j.is_discarded() || j.value("event", "") != "job_transition") continue;
    if (j.value("to", "") == "succeeded") {
      if (j.value("stored", false)) {
        ++stored_successes[j["job_id"].get<std::int64_t>()];
      } else {
        ++refused;
      }
    }
    if (j.value("to", "") == "abandoned") ++abandoned;
  }
  int twice = 0;
  for (const auto& [id, count] : stored_successes) twice += count > 1;
  EXPECT_EQ(twice, 0);
  // A killed worker's last success may not have reached its log; the database says it is there.
  EXPECT_GE(static_cast<int>(stored_successes.size()), n - 5);

  // Any API process serves any job: a second one, started now, lists them all and serves
  // the results and VTU that workers in other processes stored.
  const int second_port = testing::free_port();
  Program second({FOSLS_SERVE_PATH, "--store", cluster.url(), "--workers", "0", "--host",
                  "127.0.0.1", "--port", std::to_string(second_port)},
                 cluster.log_dir() + "/api2.log");
  second.start();
  httplib::Client cli("127.0.0.1", second_port);
  std::size_t listed = 0;
  for (int tries = 0; tries < 600 && listed == 0; ++tries) {
    std::string token;
    listed = 0;
    do {
      auto res = cli.Get("/v1/jobs?state=succeeded&page_size=100" +
                         (token.empty() ? "" : "&page_token=" + token));
      if (!res || res->status != 200) break;
      const json page = json::parse(res->body);
      listed += page["jobs"].size();
      token = page["next_page_token"].is_null() ? "" : page["next_page_token"].get<std::string>();
    } while (!token.empty());
    if (listed == 0) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_EQ(listed, static_cast<std::size_t>(n));
  for (std::size_t k : {std::size_t{0}, ids.size() / 2, ids.size() - 1}) {
    const std::string job = "/v1/jobs/" + std::to_string(ids[k]);
    auto result = cli.Get(job + "/result");
    ASSERT_TRUE(result && result->status == 200);
    EXPECT_TRUE(json::parse(result->body).contains("contact"));
    auto vtu = cli.Get(job + "/solution.vtu");
    ASSERT_TRUE(vtu && vtu->status == 200);
    EXPECT_NE(vtu->body.find("<VTKFile"), std::string::npos);
  }
  second.stop();

  // The table: how many jobs needed how many attempts.
  const auto table =
      sql_rows(cluster.url(), "SELECT attempts, count(*) FROM jobs GROUP BY attempts ORDER BY 1");
  std::printf("\n%d jobs, 1 API + %d worker processes, %.1f s; chaos:", n, kWorkers, seconds);
  for (const auto& c : chaos_log) std::printf(" [%s]", c.c_str());
  std::printf("\n| attempts | jobs |\n|---:|---:|\n");
  long long counted = 0;
  for (const auto& row : table) {
    std::printf("| %s | %s |\n", row[0].c_str(), row[1].c_str());
    counted += std::stoll(row[1]);
    EXPECT_GE(std::stoi(row[0]), 1);
  }
  EXPECT_EQ(counted, n);
  // Only a killed worker makes a job run again: at most one extra attempt per worker kill.
  EXPECT_LE(sql_count(cluster.url(), "SELECT coalesce(sum(attempts - 1), 0) FROM jobs"), 5);
  // The story of each job that ran more than once, from every program's log in time order.
  for (const auto& row :
       sql_rows(cluster.url(), "SELECT id, attempts FROM jobs WHERE attempts > 1 ORDER BY id")) {
    std::vector<std::pair<std::string, std::string>> story;  // (ts, transition)
    std::istringstream all(cluster.logs());
    for (std::string line; std::getline(all, line);) {
      const json j = json::parse(line, nullptr, false);
      if (j.is_discarded() || j.value("event", "") != "job_transition" ||
          std::to_string(j.value("job_id", std::int64_t{0})) != row[0]) {
        continue;
      }
      std::string step = " " + (j["from"].is_string() ? j["from"].get<std::string>() : "new") +
                         "→" + j["to"].get<std::string>();
      if (j.contains("reason")) step += " (" + j["reason"].get<std::string>() + ")";
      story.emplace_back(j.value("ts", ""), step);
    }
    std::sort(story.begin(), story.end());
    std::printf("job %s, %s attempts:", row[0].c_str(), row[1].c_str());
    for (const auto& [ts, step] : story) std::printf("%s", step.c_str());
    std::printf("\n");
  }
  std::printf("late completions refused: %d, runs abandoned after a lost lease: %d\n", refused,
              abandoned);
  EXPECT_EQ(chaos_log.size(), 6u);
}

/// Runs until cancelled: projected Gauss–Seidel with an unreachable tolerance.
json endless_case() {
  json j = small_case(0);
  j["name"] = "endless";
  j["mesh"]["refinements"] = 4;
  j["solver"] = {{"method", "pgs"}, {"tolerance", 1e-15}, {"max_iterations", 100000}};
  return j;
}

// A cancel taken by the API process reaches the worker process through the store (its
// heartbeat); SIGTERM of a worker puts its running job back without counting the attempt.
TEST(Cluster, CancelAndStopReachAWorkerInAnotherProcess) {
  Cluster cluster(1, 30.0);
  cluster.start_workers();
  httplib::Client cli("127.0.0.1", cluster.port());
  auto running_job = [&](const json& body) {
    auto res = cli.Post("/v1/jobs", body.dump(), "application/json");
    EXPECT_TRUE(res && res->status == 202);
    const std::string id = res ? std::to_string(json::parse(res->body)["id"].get<int>()) : "0";
    const auto give_up = Clock::now() + std::chrono::seconds(60);
    while (Clock::now() < give_up) {
      auto job = json::parse(cli.Get("/v1/jobs/" + id)->body);
      if (job["state"] == "running" && !job["progress"].is_null()) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return id;
  };

  const std::string cancelled = running_job(endless_case());
  const auto asked = Clock::now();
  ASSERT_EQ(cli.Post("/v1/jobs/" + cancelled + "/cancel")->status, 202);
  json job;
  const auto give_up = Clock::now() + std::chrono::seconds(30);
  do {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    job = json::parse(cli.Get("/v1/jobs/" + cancelled)->body);
  } while (job["state"] == "running" && Clock::now() < give_up);
  EXPECT_EQ(job["state"], "cancelled") << job;
  std::printf("cancel through the store: cancelled after %.2f s (heartbeat 0.5 s)\n",
              std::chrono::duration<double>(Clock::now() - asked).count());

  const std::string stopped = running_job(endless_case());
  cluster.worker(0).stop();  // SIGTERM
  job = json::parse(cli.Get("/v1/jobs/" + stopped)->body);
  EXPECT_EQ(job["state"], "queued") << job;
  EXPECT_EQ(job["attempts"], 0) << job;
  cli.Post("/v1/jobs/" + stopped + "/cancel");  // queued: cancelled at once
  EXPECT_EQ(json::parse(cli.Get("/v1/jobs/" + stopped)->body)["state"], "cancelled");
}

TEST(Cluster, AnApiOnlyProcessAdmitsAgainstTheWorkersDeclaredBudget) {
  // The API process has no --max-job-memory (its default is 3/4 of this host's memory); its
  // worker may give a job 100 MiB. A case estimated at about 400 MiB must be refused by the API
  // once the worker has declared its budget, not fail on the worker later.
  Cluster cluster(1, 30.0, {"--max-job-memory", "100M"});
  json big = small_case(0);
  big["mesh"]["refinements"] = 6;
  httplib::Client cli("127.0.0.1", cluster.port());
  // No worker has declared a budget yet: the API's own applies, and the job waits in the queue.
  auto before = cli.Post("/v1/jobs", big.dump(), "application/json");
  ASSERT_TRUE(before);
  EXPECT_EQ(before->status, 202) << before->body;
  cli.Post("/v1/jobs/" + std::to_string(json::parse(before->body)["id"].get<int>()) + "/cancel");
  cluster.start_workers();
  std::string detail;
  const auto give_up = Clock::now() + std::chrono::seconds(60);
  while (Clock::now() < give_up) {  // the API reads the declarations every 2 s
    auto res = cli.Post("/v1/jobs", big.dump(), "application/json");
    ASSERT_TRUE(res);
    if (res->status == 422) {
      detail = json::parse(res->body)["errors"][0]["detail"];
      break;
    }
    cli.Post("/v1/jobs/" + std::to_string(json::parse(res->body)["id"].get<int>()) + "/cancel");
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  std::printf("API-only admission after the worker declared: %s\n", detail.c_str());
  EXPECT_NE(detail.find("more than the 100 MiB a job may use (the workers' --max-job-memory"),
            std::string::npos)
      << detail;
  EXPECT_EQ(sql_count(cluster.url(), "SELECT max_job_memory FROM worker_budgets"), 100 << 20);
}

/// The 1-minute load average, to print beside a measurement on a shared machine.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return one;
}

// Jobs per minute with W worker processes (one solver thread each), all jobs queued before the
// workers start; measured from the start of the workers to the last job finished. Rounds
// interleave 1, 2 and 4 processes so that the machine's other load falls on all of them.
TEST(Cluster, DISABLED_Throughput) {
  const int n = env_int("FOSLS_CLUSTER_JOBS", 120);
  const int rounds = env_int("FOSLS_CLUSTER_ROUNDS", 1);
  std::printf(
      "\n| round | worker processes | jobs | seconds | jobs per minute | worker CPU s per job "
      "| load before |\n|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int round = 1; round <= rounds; ++round) {
    for (int workers : {1, 2, 4}) {
      Cluster cluster(workers, 30.0);
      post_jobs(cluster, n, 8);
      const std::string load = load_average();
      const auto started = Clock::now();
      cluster.start_workers();
      ASSERT_TRUE(cluster.wait_all_finished(n, 900));
      const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
      const double cpu = cluster.worker_cpu_seconds();
      EXPECT_EQ(sql_count(cluster.url(), "SELECT count(*) FROM jobs WHERE state = 'succeeded'"), n);
      std::printf("| %d | %d | %d | %.1f | %.0f | %.3f | %s |\n", round, workers, n, seconds,
                  60.0 * n / seconds, cpu / n, load.c_str());
      std::fflush(stdout);
    }
  }
}

// What the store costs per job, without solving: submit, claim, a heartbeat, two progress
// writes and the completion with a result and a VTU of the small case's size, by `threads`
// threads of one process on one PostgreSQL server (the bound the database puts on throughput).
TEST(Cluster, DISABLED_StoreOnlyRate) {
  PostgresCluster pg;
  PostgresJobStore store(pg.create_database("rate"));
  std::string vtu;
  while (vtu.size() < 60000) vtu += "<DataArray>0.125 0.25 0.5 1.0</DataArray>\n";
  std::printf("\n| threads | jobs | seconds | jobs per second |\n|---:|---:|---:|---:|\n");
  for (int threads : {1, 4}) {
    constexpr int kPerThread = 300;
    const auto started = Clock::now();
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) {
      pool.emplace_back([&, t] {
        for (int i = 0; i < kPerThread; ++i) {
          NewJob job;
          job.name = "rate";
          job.case_json = small_case(t * kPerThread + i).dump();
          job.body_hash = sha256_hex(job.case_json);
          store.submit(job, 1'000'000);
          auto claimed =
              store.claim_next(ClaimRequest{"w" + std::to_string(t), std::chrono::minutes(1)});
          if (!claimed) continue;
          store.renew_lease(claimed->lease, std::chrono::minutes(1));
          store.update_progress(claimed->lease, JobProgress{1, 0.5, -1});
          store.update_progress(claimed->lease, JobProgress{28, 1e-9, -2});
          store.complete_succeeded(claimed->lease, R"({"converged":true})", vtu);
        }
      });
    }
    for (auto& t : pool) t.join();
    const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
    std::printf("| %d | %d | %.2f | %.0f |\n", threads, threads * kPerThread, seconds,
                threads * kPerThread / seconds);
  }
}

}  // namespace
}  // namespace fosls::service
