#pragma once
// What a hostile-use probe measures of the server while it runs: its resident memory (from
// /proc, sampled) and how long /healthz takes, asked every 20 ms on one kept-alive connection.
// The numbers are printed for docs/service.md; the tests assert bounds with a wide margin.

#include <httplib.h>
#include <sys/types.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace fosls::service::testing {

constexpr std::size_t kMiB = 1024 * 1024;

/// A line of /proc/PID/status in bytes ("VmRSS", "VmHWM").
inline std::size_t proc_status_bytes(pid_t pid, const std::string& key) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + ":", 0) == 0) return std::stoull(line.substr(key.size() + 1)) * 1024;
  return 0;
}

inline double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(p * (v.size() - 1))];
}

/// Watches a server from construction to stop(): /healthz latencies and the largest resident
/// memory sampled (every 20 ms, and at the ends).
class ServerWatch {
 public:
  ServerWatch(pid_t pid, int port)
      : pid_(pid),
        before_(proc_status_bytes(pid, "VmRSS")),
        peak_(before_),
        client_("127.0.0.1", port) {
    client_.set_keep_alive(true);
    client_.set_read_timeout(std::chrono::seconds(60));
    thread_ = std::thread([this] { run(); });
  }
  ~ServerWatch() { stop(); }
  ServerWatch(const ServerWatch&) = delete;
  ServerWatch& operator=(const ServerWatch&) = delete;

  /// Ends the watch; the memory after is read `settle` later (freed memory going back).
  void stop(std::chrono::milliseconds settle = std::chrono::milliseconds(0)) {
    if (!thread_.joinable()) return;
    running_ = false;
    thread_.join();
    std::this_thread::sleep_for(settle);
    after_ = proc_status_bytes(pid_, "VmRSS");
    peak_ = std::max(peak_, after_);
  }

  std::size_t before() const { return before_; }
  std::size_t peak() const { return peak_; }
  std::size_t after() const { return after_; }
  std::vector<double> health_ms() const {
    std::lock_guard lock(mutex_);
    return health_ms_;
  }
  int health_failures() const { return failures_; }

  /// "RSS 21 → peak 40 → 22 MiB; /healthz 120 answers, median 0.4, p90 2.1, max 30 ms".
  std::string summary() const {
    const std::vector<double> ms = health_ms();
    char text[300];
    std::snprintf(text, sizeof text,
                  "RSS %.0f -> peak %.0f -> %.0f MiB; /healthz %zu answers, median %.1f, p90 %.1f, "
                  "max %.1f ms",
                  before_ / double(kMiB), peak_ / double(kMiB), after_ / double(kMiB), ms.size(),
                  percentile(ms, 0.5), percentile(ms, 0.9), percentile(ms, 1.0));
    return text;
  }

 private:
  void run() {
    while (running_) {
      peak_ = std::max(peak_, proc_status_bytes(pid_, "VmRSS"));
      const auto t0 = std::chrono::steady_clock::now();
      auto res = client_.Get("/healthz");
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (!res || res->status != 200) ++failures_;
      {
        std::lock_guard lock(mutex_);
        health_ms_.push_back(ms);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }

  pid_t pid_;
  std::size_t before_, peak_, after_ = 0;
  httplib::Client client_;
  std::atomic<bool> running_{true};
  std::atomic<int> failures_{0};
  mutable std::mutex mutex_;
  std::vector<double> health_ms_;
  std::thread thread_;
};

}  // namespace fosls::service::testing
