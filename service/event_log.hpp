#pragma once
// Structured log: one JSON object per line (stderr in the service), so every request and job
// transition can be filtered and parsed by machines.

#include <mutex>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string_view>

namespace fosls::service {

/// Writes one JSON line per event; safe to call from many threads.
class EventLog {
 public:
  /// Logs to `out`, which must outlive the log (std::cerr in the service).
  explicit EventLog(std::ostream& out) : out_(out) {}

  /// Writes `fields` with "ts" (RFC 3339) and "event" added, as one line. Strings that are
  /// not valid UTF-8 (for example raw bytes of a request path) are replaced, never thrown.
  void write(std::string_view event, nlohmann::json fields = nlohmann::json::object());

 private:
  std::ostream& out_;
  std::mutex mutex_;
};

}  // namespace fosls::service
