#include "event_log.hpp"

#include "job.hpp"

namespace fosls::service {

void EventLog::write(std::string_view event, nlohmann::json fields) {
  if (!fields.is_object()) fields = {{"value", std::move(fields)}};
  fields["ts"] = format_rfc3339(now_unix_ms());
  fields["event"] = std::string(event);
  const std::string line =
      fields.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  std::lock_guard lock(mutex_);
  out_ << line << std::flush;
}

}  // namespace fosls::service
