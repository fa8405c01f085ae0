// fosls-serve: the HTTP job service. Queues contact cases in SQLite and solves them on
// in-process worker threads (docs/service.md).
//
//   fosls-serve                               # http://127.0.0.1:8080, ./data/fosls.db
//   fosls-serve --port 0 --db /tmp/jobs.db    # a free port, printed on stdout
//   fosls-serve --host 0.0.0.0 --workers 2    # in a container

#include <fcntl.h>
#include <httplib.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <thread>

#include "case_job_runner.hpp"
#include "event_log.hpp"
#include "http_api.hpp"
#include "metrics.hpp"
#include "retention_sweeper.hpp"
#include "sqlite_job_store.hpp"
#include "worker_pool.hpp"

namespace {

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string db = "data/fosls.db";
  int workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  int http_threads = 16;
  std::string web_root = FOSLS_SOURCE_DIR "/web";
  std::size_t max_queue = 1000;
  std::size_t max_body_bytes = 8u << 20;
  double retention_hours = 168;
  int max_attempts = 3;
};

std::string url_host(const std::string& host) {
  return host.find(':') != std::string::npos ? "[" + host + "]" : host;
}

int serve(const ServeOptions& o, const sigset_t& stop_signals) {
  using namespace fosls::service;
  EventLog log(std::cerr);

  const std::filesystem::path db_path(o.db);
  if (db_path.has_parent_path()) std::filesystem::create_directories(db_path.parent_path());
  // Start-up recovery assumes this process owns every running job of the database; a
  // second server on the same file would re-queue the first one's jobs. The kernel drops
  // the lock when the process dies, also on kill -9. The descriptor stays open until exit.
  const std::string lock_path = o.db + ".lock";
  const int lock_fd = open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd < 0 || flock(lock_fd, LOCK_EX | LOCK_NB) != 0) {
    std::cerr << "fosls-serve: another fosls-serve is using " << o.db << " (lock " << lock_path
              << ")\n";
    return 1;
  }
  SqliteJobStore store(o.db);
  const RecoveryReport recovery = store.recover_interrupted(o.max_attempts);
  for (auto id : recovery.requeued) {
    log.write("job_transition", {{"job_id", id},
                                 {"from", "running"},
                                 {"to", "queued"},
                                 {"reason", "recovered after the previous process stopped"}});
  }
  for (auto id : recovery.failed) {
    log.write("job_transition", {{"job_id", id},
                                 {"from", "running"},
                                 {"to", "failed"},
                                 {"reason", "max attempts reached"}});
  }
  for (auto id : recovery.cancelled) {
    log.write("job_transition", {{"job_id", id}, {"from", "running"}, {"to", "cancelled"}});
  }

  Metrics metrics;
  WorkerPoolOptions pool_options;
  pool_options.workers = o.workers;
  WorkerPool pool(store, run_case_job, log, metrics, pool_options);

  HttpApiOptions api_options;
  api_options.max_queue = o.max_queue;
  api_options.max_body_bytes = o.max_body_bytes;
  api_options.web_root = o.web_root;
  HttpApi api(store, pool, validate_submitted_case, metrics, log, api_options);

  httplib::Server server;
  // The Debian library is compiled: CPPHTTPLIB_THREAD_POOL_COUNT has no effect, only this.
  const int http_threads = o.http_threads;
  server.new_task_queue = [http_threads] { return new httplib::ThreadPool(http_threads); };
  server.set_keep_alive_timeout(2);  // idle keep-alive connections delay shutdown this long
  server.set_keep_alive_max_count(1000);
  api.install(server);

  const int port = o.port == 0 ? server.bind_to_any_port(o.host)
                               : (server.bind_to_port(o.host, o.port) ? o.port : -1);
  if (port < 0) {
    std::cerr << "fosls-serve: cannot listen on " << o.host << ":" << o.port
              << " (address in use or not available)\n";
    return 1;
  }
  std::cout << "listening on http://" << url_host(o.host) << ":" << port << std::endl;
  log.write("started", {{"host", o.host},
                        {"port", port},
                        {"db", o.db},
                        {"workers", pool.size()},
                        {"http_threads", http_threads},
                        {"web_root", o.web_root},
                        {"recovered", recovery.requeued.size()}});

  pool.start();
  std::unique_ptr<RetentionSweeper> sweeper;
  if (o.retention_hours > 0) {
    const auto retention =
        std::chrono::milliseconds(static_cast<std::int64_t>(o.retention_hours * 3600.0 * 1000.0));
    const auto interval = std::clamp(retention / 4, std::chrono::milliseconds(1000),
                                     std::chrono::milliseconds(10 * 60 * 1000));
    sweeper = std::make_unique<RetentionSweeper>(store, log, retention, interval);
    sweeper->start();
  }

  std::atomic<bool> stopping{false};
  std::thread http([&] {
    if (!server.listen_after_bind()) log.write("http_error", {{"error", "listen failed"}});
    // Wake the main thread if the server ended on its own (not through stop() below).
    if (!stopping.load()) kill(getpid(), SIGTERM);
  });

  int signal_number = 0;
  sigwait(&stop_signals, &signal_number);
  log.write("stopping", {{"signal", signal_number}});
  // A second signal means "now": running jobs are recovered at the next start.
  std::thread([stop_signals] {
    int again = 0;
    sigwait(&stop_signals, &again);
    std::_Exit(128 + again);
  }).detach();

  stopping = true;
  pool.begin_shutdown();  // running solves see their cancel flag and go back to the queue
  server.stop();          // stop accepting; finishes requests in progress
  http.join();
  pool.join();
  if (sweeper) sweeper->stop();
  log.write("stopped", {{"busy_workers", pool.busy()}});
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  ServeOptions o;
  CLI::App app{"fosls-serve: HTTP job service for FOSLS contact cases (docs/service.md)"};
  app.add_option("--host", o.host, "Address to listen on")->capture_default_str();
  app.add_option("--port", o.port, "TCP port; 0 picks a free port (printed on start)")
      ->check(CLI::Range(0, 65535))
      ->capture_default_str();
  app.add_option("--db", o.db, "SQLite database file (its folder is created)")
      ->capture_default_str();
  app.add_option("--workers", o.workers, "Solver threads (default: hardware cores)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
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
  app.add_option("--max-attempts", o.max_attempts,
                 "Starts after which a job interrupted by a crash is failed")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  // Block the stop signals in every thread (threads inherit the mask) and take them with
  // sigwait, so shutdown runs as ordinary code instead of inside a signal handler.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);  // a client closing early must not kill the process

  try {
    return serve(o, stop_signals);
  } catch (const std::exception& e) {
    std::cerr << "fosls-serve: " << e.what() << "\n";
    return 1;
  }
}
