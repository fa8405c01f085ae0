// fosls-serve: the HTTP job service. Queues contact cases in a job store (SQLite, or
// PostgreSQL shared with other processes) and solves them on in-process worker threads
// (docs/service.md).
//
//   fosls-serve                               # http://127.0.0.1:8080, ./data/fosls.db
//   fosls-serve --port 0 --db /tmp/jobs.db    # a free port, printed on stdout
//   fosls-serve --host 0.0.0.0 --workers 2    # in a container
//   fosls-serve --store postgresql://fosls@db/fosls --workers 0   # API only; fosls-worker solves

#include <httplib.h>
#include <signal.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <iostream>
#include <thread>

#include "bounded_http_server.hpp"
#include "case_job_runner.hpp"
#include "elastic_thread_pool.hpp"
#include "event_log.hpp"
#include "http_api.hpp"
#include "lease_reaper.hpp"
#include "metrics.hpp"
#include "process/malloc_arenas.hpp"
#include "retention_sweeper.hpp"
#include "store_url.hpp"
#include "worker_options.hpp"
#include "worker_pool.hpp"

namespace {

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;
  fosls::service::WorkerOptions worker;  // --store, --workers, leases
  std::string db;                        // --db PATH: synonym of --store sqlite:PATH
  int http_threads = 16;
  std::string web_root = FOSLS_SOURCE_DIR "/web";
  std::size_t max_queue = 1000;
  std::size_t max_body_bytes = 8u << 20;
  double retention_hours = 168;
};

std::string url_host(const std::string& host) {
  return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

/// A --workers 0 process on SQLite queues jobs nothing can solve: said once at start.
void warn_if_nothing_solves(fosls::service::EventLog& log, const ServeOptions& o,
                            const fosls::service::OpenedStore& opened) {
  using fosls::service::StoreLocation;
  if (o.worker.workers == 0 && opened.location.kind == StoreLocation::Kind::kSqlite) {
    log.write("warning", {{"message",
                           "--workers 0 on a sqlite: store: nothing will solve the jobs queued "
                           "here (a SQLite file belongs to one process; fosls-worker needs "
                           "--store postgresql://…)"}});
  }
}

fosls::service::HttpApiOptions api_options(const ServeOptions& o) {
  fosls::service::HttpApiOptions api_options;
  api_options.max_queue = o.max_queue;
  api_options.max_body_bytes = o.max_body_bytes;
  api_options.web_root = o.web_root;
  // Large submissions are read on low-priority threads, one per core.
  api_options.admission_threads =
      static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return api_options;
}

void configure_http_threads(fosls::service::BoundedHttpServer& server, int http_threads) {
  // The Debian library is compiled: CPPHTTPLIB_THREAD_POOL_COUNT has no effect, only this.
  // Grows up to 16 times that while every thread holds a connection, so slow or silent
  // clients cannot keep /healthz and everyone else waiting; a silent one is dropped after
  // the read timeout.
  server.new_task_queue = [http_threads] {
    return new fosls::service::ElasticThreadPool(http_threads, 16 * http_threads);
  };
  server.set_read_timeout(2);
  server.set_keep_alive_timeout(2);
  server.set_keep_alive_max_count(1000);
}

/// The port listened on (--port 0: a free one), or -1 after saying why not.
int bind_port(fosls::service::BoundedHttpServer& server, const ServeOptions& o) {
  const int port = o.port == 0 ? server.bind_to_any_port(o.host)
                               : (server.bind_to_port(o.host, o.port) ? o.port : -1);
  if (port < 0) {
    std::cerr << "fosls-serve: cannot listen on " << o.host << ":" << o.port
              << " (address in use or not available)\n";
  }
  return port;
}

/// The retention sweeper, started, or none when --retention-hours is 0.
std::unique_ptr<fosls::service::RetentionSweeper> start_sweeper(fosls::service::JobStore& store,
                                                                fosls::service::EventLog& log,
                                                                double retention_hours) {
  if (retention_hours <= 0) return nullptr;
  const auto retention =
      std::chrono::milliseconds(static_cast<std::int64_t>(retention_hours * 3600.0 * 1000.0));
  const auto interval = std::clamp(retention / 4, std::chrono::milliseconds(1000),
                                   std::chrono::milliseconds(10 * 60 * 1000));
  auto sweeper =
      std::make_unique<fosls::service::RetentionSweeper>(store, log, retention, interval);
  sweeper->start();
  return sweeper;
}

/// Serves on the bound server until a stop signal (or the server ending on its own), then
/// stops accepting and lets running solves go back to the queue.
void serve_until_stopped(fosls::service::BoundedHttpServer& server,
                         fosls::service::WorkerPool& pool, fosls::service::EventLog& log,
                         const sigset_t& stop_signals) {
  std::atomic<bool> stopping{false};
  std::thread http([&] {
    if (!server.listen_after_bind()) log.write("http_error", {{"error", "listen failed"}});
    // Wake the main thread if the server ended on its own (not through stop() below).
    if (!stopping.load()) kill(getpid(), SIGTERM);
  });

  const int signal_number = fosls::service::wait_for_stop_signal(stop_signals);
  log.write("stopping", {{"signal", signal_number}});

  stopping = true;
  pool.begin_shutdown();  // running solves see their cancel flag and go back to the queue
  server.stop();          // stop accepting; finishes requests in progress
  http.join();
  pool.join();
}

int serve(const ServeOptions& o, const sigset_t& stop_signals) {
  using namespace fosls::service;
  EventLog log(std::cerr);

  OpenedStore opened;
  try {
    opened = open_store(parse_store_url(o.worker.store), "fosls-serve", o.worker.max_attempts);
  } catch (const std::exception& e) {
    std::cerr << "fosls-serve: " << e.what() << "\n";
    return 1;
  }
  JobStore& store = *opened.store;
  log_recovery(log, opened.recovered, opened.recovery_reason);
  warn_if_nothing_solves(log, o, opened);

  Metrics metrics;
  WorkerPool pool(store, service_job_runner(o.worker), log, metrics, o.worker.pool_options());

  // Cases are admitted against what the workers declared in the store (an API-only process
  // included), against this process's own budget until one has (admission_budget.hpp).
  AdmissionBudget budget(store, o.worker.job_memory_bytes());
  std::function<MemoryBudget()> admission;
  if (!o.worker.admit_over_budget) admission = [&budget] { return budget.current(); };
  HttpApi api(store, pool, submitted_case_validator(admission, o.worker.max_job_seconds), metrics,
              log, api_options(o));

  // Request heads are read under limits before cpp-httplib parses them (bounded_http_server.hpp).
  BoundedHttpServer server;
  configure_http_threads(server, o.http_threads);
  api.install(server);

  const int port = bind_port(server, o);
  if (port < 0) return 1;
  std::cout << "listening on http://" << url_host(o.host) << ":" << port << std::endl;
  log.write("started", {{"host", o.host},
                        {"port", port},
                        {"store", redacted(opened.location)},
                        {"workers", pool.size()},
                        {"http_threads", o.http_threads},
                        {"web_root", o.web_root},
                        {"recovered", opened.recovered.requeued.size()}});

  pool.start();
  std::unique_ptr<RetentionSweeper> sweeper = start_sweeper(store, log, o.retention_hours);
  // Every process on a shared store takes back the jobs of workers that died (the SQLite
  // owner recovered its file's running jobs above; its own leases only expire if a worker
  // thread stops renewing them).
  LeaseReaper reaper(store, log, o.worker.max_attempts, o.worker.reaper_interval());
  reaper.start();

  serve_until_stopped(server, pool, log, stop_signals);
  if (sweeper) sweeper->stop();
  reaper.stop();
  log.write("stopped", {{"busy_workers", pool.busy()}});
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // A large request's buffers go back to the system when freed (malloc_arenas.hpp).
  fosls::give_large_blocks_back();
  ServeOptions o;
  o.worker.workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  CLI::App app{"fosls-serve: HTTP job service for FOSLS contact cases (docs/service.md)"};
  app.add_option("--host", o.host, "Address to listen on")->capture_default_str();
  app.add_option("--port", o.port, "TCP port; 0 picks a free port (printed on start)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  fosls::service::add_worker_options(app, o.worker, 0);
  auto* db_option = app.add_option("--db", o.db, "SQLite database file: --store sqlite:PATH");
  app.add_option("--http-threads", o.http_threads, "Threads serving HTTP connections")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  app.add_option("--web-root", o.web_root, "Folder served at / (the web page)")
      ->capture_default_str();
  app.add_option("--max-queue", o.max_queue, "Queued jobs beyond which POST gets 503")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}))
      ->capture_default_str();
  app.add_option("--max-body-bytes", o.max_body_bytes, "Largest accepted request body")
      ->check(CLI::Range(std::size_t{1024}, std::size_t{1} << 30))
      ->capture_default_str();
  app.add_option("--retention-hours", o.retention_hours,
                 "Delete finished jobs older than this (0 keeps them)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  db_option->excludes(app.get_option("--store"));
  CLI11_PARSE(app, argc, argv);
  if (const std::string problem = o.worker.problem(); !problem.empty()) {
    std::cerr << "fosls-serve: " << problem << "\n";
    return 2;
  }
  if (!o.db.empty()) o.worker.store = "sqlite:" + o.db;

  // Blocked in every thread (threads inherit the mask) and taken with sigwait, so shutdown
  // runs as ordinary code instead of inside a signal handler.
  const sigset_t stop_signals = fosls::service::block_stop_signals();

  try {
    return serve(o, stop_signals);
  } catch (const std::exception& e) {
    std::cerr << "fosls-serve: " << e.what() << "\n";
    return 1;
  }
}
