#include "metrics.hpp"

#include <cstdio>

namespace fosls::service {

namespace {
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string join_labels(const std::string& a, const std::string& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return a + "," + b;
}

// Solves range from milliseconds (tiny cases) to many minutes (fine meshes).
std::vector<double> run_bounds() {
  return {0.05, 0.1, 0.25, 0.5, 1, 2.5, 5, 10, 30, 60, 300, 1800};
}
}  // namespace

Histogram::Histogram(std::vector<double> upper_bounds)
    : upper_bounds_(std::move(upper_bounds)), counts_(upper_bounds_.size() + 1, 0) {}

void Histogram::observe(double value) {
  std::size_t i = 0;
  while (i < upper_bounds_.size() && value > upper_bounds_[i]) ++i;
  ++counts_[i];
  sum_ += value;
  ++count_;
}

void Histogram::render(std::string& out, const std::string& name, const std::string& labels) const {
  std::uint64_t cumulative = 0;
  for (std::size_t i = 0; i <= upper_bounds_.size(); ++i) {
    cumulative += counts_[i];
    const std::string le =
        "le=\"" + (i < upper_bounds_.size() ? number(upper_bounds_[i]) : std::string("+Inf")) +
        "\"";
    out += name + "_bucket{" + join_labels(labels, le) + "} " + std::to_string(cumulative) + "\n";
  }
  const std::string braces = labels.empty() ? "" : "{" + labels + "}";
  out += name + "_sum" + braces + " " + number(sum_) + "\n";
  out += name + "_count" + braces + " " + std::to_string(count_) + "\n";
}

Metrics::Metrics()
    : http_seconds_({0.001, 0.0025, 0.005, 0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1, 2.5}) {}

void Metrics::record_http(const std::string& method, const std::string& route, int status,
                          double seconds) {
  std::lock_guard lock(mutex_);
  ++http_requests_[{method, route, status}];
  http_seconds_.observe(seconds);
}

void Metrics::record_run(JobState outcome, double seconds) {
  std::lock_guard lock(mutex_);
  auto it = run_seconds_.find(outcome);
  if (it == run_seconds_.end()) it = run_seconds_.emplace(outcome, Histogram(run_bounds())).first;
  it->second.observe(seconds);
}

void Metrics::record_stop_reason(const std::string& stop_reason) {
  std::lock_guard lock(mutex_);
  // Results without the field (older solvers, test doubles) are counted, not dropped.
  ++stop_reasons_[stop_reason.empty() ? "unknown" : stop_reason];
}

std::string Metrics::render(const MetricsSnapshot& snapshot) const {
  std::string out;
  out += "# HELP fosls_jobs Jobs in the store by state.\n# TYPE fosls_jobs gauge\n";
  for (JobState s : kAllJobStates) {
    auto it = snapshot.jobs_by_state.find(s);
    const std::int64_t n = it == snapshot.jobs_by_state.end() ? 0 : it->second;
    out += "fosls_jobs{state=\"" + std::string(to_string(s)) + "\"} " + std::to_string(n) + "\n";
  }
  auto queued = snapshot.jobs_by_state.find(JobState::kQueued);
  out += "# HELP fosls_queue_depth Jobs waiting for a worker.\n# TYPE fosls_queue_depth gauge\n";
  out += "fosls_queue_depth " +
         std::to_string(queued == snapshot.jobs_by_state.end() ? 0 : queued->second) + "\n";
  out +=
      "# HELP fosls_jobs_not_converged Jobs in the store whose solve stopped without "
      "converging.\n# TYPE fosls_jobs_not_converged gauge\n";
  out += "fosls_jobs_not_converged " + std::to_string(snapshot.not_converged) + "\n";
  out += "# HELP fosls_workers Solver worker threads.\n# TYPE fosls_workers gauge\n";
  out += "fosls_workers " + std::to_string(snapshot.workers) + "\n";
  out += "# HELP fosls_workers_busy Workers solving a job now.\n# TYPE fosls_workers_busy gauge\n";
  out += "fosls_workers_busy " + std::to_string(snapshot.busy_workers) + "\n";

  std::lock_guard lock(mutex_);
  out +=
      "# HELP fosls_job_run_seconds Wall time of solve attempts by outcome.\n"
      "# TYPE fosls_job_run_seconds histogram\n";
  for (const auto& [outcome, histogram] : run_seconds_) {
    histogram.render(out, "fosls_job_run_seconds",
                     "outcome=\"" + std::string(to_string(outcome)) + "\"");
  }
  out +=
      "# HELP fosls_solves_total Solves of this process that produced a result, by why they "
      "stopped.\n# TYPE fosls_solves_total counter\n";
  for (const auto& [reason, n] : stop_reasons_)
    out += "fosls_solves_total{stop_reason=\"" + reason + "\"} " + std::to_string(n) + "\n";
  out +=
      "# HELP fosls_http_requests_total HTTP requests by method, route and status.\n"
      "# TYPE fosls_http_requests_total counter\n";
  for (const auto& [key, n] : http_requests_) {
    const auto& [method, route, status] = key;
    out += "fosls_http_requests_total{method=\"" + method + "\",route=\"" + route + "\",status=\"" +
           std::to_string(status) + "\"} " + std::to_string(n) + "\n";
  }
  out +=
      "# HELP fosls_http_request_seconds Time to handle HTTP requests.\n"
      "# TYPE fosls_http_request_seconds histogram\n";
  http_seconds_.render(out, "fosls_http_request_seconds", "");
  return out;
}

}  // namespace fosls::service
