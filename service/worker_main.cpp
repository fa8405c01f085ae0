// fosls-worker: the solver workers of the job service without HTTP, on any host that reaches
// the job store (docs/service.md, "Several hosts").
//
//   fosls-worker --store postgresql://fosls:secret@db-host/fosls --workers 2

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <thread>

#include "event_log.hpp"
#include "lease_reaper.hpp"
#include "metrics.hpp"
#include "store_url.hpp"
#include "worker_options.hpp"
#include "worker_pool.hpp"

namespace {

int work(const fosls::service::WorkerOptions& o, const sigset_t& stop_signals) {
  using namespace fosls::service;
  EventLog log(std::cerr);
  OpenedStore opened;
  try {
    opened = open_store(parse_store_url(o.store), "fosls-worker", o.max_attempts);
  } catch (const std::exception& e) {
    std::cerr << "fosls-worker: " << e.what() << "\n";
    return 1;
  }
  log_recovery(log, opened.recovered, opened.recovery_reason);
  Metrics metrics;  // recorded for the log only: this process serves no /metrics
  WorkerPoolOptions pool_options = o.pool_options();
  WorkerPool pool(*opened.store, service_job_runner(o), log, metrics, pool_options);
  LeaseReaper reaper(*opened.store, log, o.max_attempts, o.reaper_interval());
  log.write("started", {{"program", "fosls-worker"},
                        {"store", redacted(opened.location)},
                        {"workers", pool.size()},
                        {"lease_seconds", o.lease_seconds}});
  pool.start();
  reaper.start();

  const int signal_number = wait_for_stop_signal(stop_signals);
  log.write("stopping", {{"signal", signal_number}});
  pool.begin_shutdown();  // running solves see their cancel flag and go back to the queue
  pool.join();
  reaper.stop();
  log.write("stopped", {{"busy_workers", pool.busy()}});
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  fosls::service::WorkerOptions o;
  o.workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  o.store.clear();  // required: no default to show
  CLI::App app{
      "fosls-worker: solver workers of the FOSLS contact job service, without HTTP "
      "(docs/service.md)"};
  fosls::service::add_worker_options(app, o, 1);
  app.get_option("--store")->required();
  CLI11_PARSE(app, argc, argv);
  if (const std::string problem = o.problem(); !problem.empty()) {
    std::cerr << "fosls-worker: " << problem << "\n";
    return 2;
  }
  const sigset_t stop_signals = fosls::service::block_stop_signals();
  try {
    return work(o, stop_signals);
  } catch (const std::exception& e) {
    std::cerr << "fosls-worker: " << e.what() << "\n";
    return 1;
  }
}
