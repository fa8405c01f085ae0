#pragma once
// Counters and histograms for GET /metrics (Prometheus text exposition format 0.0.4).

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

#include "job.hpp"

namespace fosls::service {

/// Cumulative histogram with fixed upper bounds (Prometheus "le" buckets, +Inf implied).
class Histogram {
 public:
  explicit Histogram(std::vector<double> upper_bounds);
  void observe(double value);
  /// Appends the _bucket, _sum and _count lines of `name` with extra `labels` ("" or "k=\"v\"").
  void render(std::string& out, const std::string& name, const std::string& labels) const;

 private:
  std::vector<double> upper_bounds_;
  std::vector<std::uint64_t> counts_;  ///< per bucket, not cumulative; last is +Inf
  double sum_ = 0.0;
  std::uint64_t count_ = 0;
};

/// Gauges that are read from elsewhere at scrape time.
struct MetricsSnapshot {
  std::map<JobState, std::int64_t> jobs_by_state;
  std::int64_t not_converged = 0;  ///< jobs whose solve stopped without converging
  int workers = 0;
  int busy_workers = 0;
};

/// The service's metrics; safe to update from many threads.
class Metrics {
 public:
  Metrics();

  /// One HTTP request: `route` is a template such as "/v1/jobs/{id}" (bounded label values).
  void record_http(const std::string& method, const std::string& route, int status, double seconds);

  /// One finished solve attempt and its wall time in seconds.
  void record_run(JobState outcome, double seconds);

  /// How one solve that produced a result stopped ("converged", "max_iterations", …).
  void record_stop_reason(const std::string& stop_reason);

  /// The exposition text.
  std::string render(const MetricsSnapshot& snapshot) const;

 private:
  mutable std::mutex mutex_;
  std::map<std::tuple<std::string, std::string, int>, std::uint64_t> http_requests_;
  Histogram http_seconds_;
  std::map<JobState, Histogram> run_seconds_;
  std::map<std::string, std::uint64_t> stop_reasons_;
};

}  // namespace fosls::service
