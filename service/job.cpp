#include "job.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "openapi_builders.hpp"

namespace fosls::service {

std::string_view to_string(JobState state) {
  switch (state) {
    case JobState::kQueued:
      return "queued";
    case JobState::kRunning:
      return "running";
    case JobState::kSucceeded:
      return "succeeded";
    case JobState::kFailed:
      return "failed";
    case JobState::kCancelled:
      return "cancelled";
  }
  return "unknown";
}

std::optional<JobState> parse_job_state(std::string_view text) {
  for (JobState s : kAllJobStates) {
    if (to_string(s) == text) return s;
  }
  return std::nullopt;
}

bool is_finished(JobState state) {
  return state == JobState::kSucceeded || state == JobState::kFailed ||
         state == JobState::kCancelled;
}

namespace {
nlohmann::json optional_time(const std::optional<std::int64_t>& ms) {
  return ms ? nlohmann::json(format_rfc3339(*ms)) : nlohmann::json(nullptr);
}

// JSON has no NaN or infinity; a diverging solve reports them, so they become null.
nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}
}  // namespace

JobConvergence convergence_of_result(const std::string& result_json) {
  JobConvergence c;
  const nlohmann::json r = nlohmann::json::parse(result_json, nullptr, false);
  if (!r.is_object()) return c;
  if (auto it = r.find("converged"); it != r.end() && it->is_boolean())
    c.converged = it->get<bool>();
  if (auto it = r.find("stop_reason"); it != r.end() && it->is_string())
    c.stop_reason = it->get<std::string>();
  return c;
}

nlohmann::json job_to_json(const Job& job) {
  const std::string self = "/v1/jobs/" + std::to_string(job.id);
  nlohmann::json j = {
      {"id", job.id},
      {"name", job.name},
      {"state", to_string(job.state)},
      {"created_at", format_rfc3339(job.created_at_ms)},
      {"started_at", optional_time(job.started_at_ms)},
      {"finished_at", optional_time(job.finished_at_ms)},
      {"attempts", job.attempts},
      {"cancel_requested", job.cancel_requested},
      {"error", job.error.empty() ? nlohmann::json(nullptr) : nlohmann::json(job.error)},
      {"converged", job.convergence.converged ? nlohmann::json(*job.convergence.converged)
                                              : nlohmann::json(nullptr)},
      {"stop_reason", job.convergence.stop_reason.empty()
                          ? nlohmann::json(nullptr)
                          : nlohmann::json(job.convergence.stop_reason)},
      {"links",
       {{"self", self},
        {"case", self + "/case"},
        {"result", self + "/result"},
        {"solution", self + "/solution.vtu"},
        {"cancel", self + "/cancel"}}},
  };
  if (job.progress) {
    const JobProgress& p = *job.progress;
    j["progress"] = {{"iteration", p.iteration},
                     {"kkt_residual", finite_or_null(p.kkt_residual)},
                     {"energy", finite_or_null(p.energy)},
                     {"step", p.step},
                     {"steps", p.steps > 0 ? nlohmann::json(p.steps) : nlohmann::json(nullptr)}};
  } else {
    j["progress"] = nullptr;
  }
  return j;
}

nlohmann::json job_json_schema() {
  using nlohmann::json;
  using openapi::nullable;
  using openapi::string_field;
  json links = {{"type", "object"},
                {"additionalProperties", false},
                {"required", {"self", "result", "solution", "cancel", "case"}},
                {"properties",
                 {{"self", string_field("this job")},
                  {"result", string_field("its result JSON")},
                  {"solution", string_field("its VTU file")},
                  {"cancel", string_field("POST here to cancel it")},
                  {"case", string_field("the case as submitted")}}}};
  json progress = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"iteration", "kkt_residual", "energy", "step", "steps"}},
      {"properties",
       {{"iteration",
         {{"type", "integer"}, {"minimum", 0}, {"description", "counted from 0 in each solve"}}},
        {"kkt_residual", nullable({{"type", "number"}})},
        {"energy", nullable({{"type", "number"}, {"description", "the scaled functional J"}})},
        {"step",
         {{"type", "integer"},
          {"minimum", 0},
          {"description",
           "the solve running, 0 first: the load step, sweep point, or adaptive or accuracy "
           "level (every level of every point for a sweep with adaptivity); 0 for one solve"}}},
        {"steps", nullable({{"type", "integer"},
                            {"minimum", 1},
                            {"description",
                             "how many solves the job makes at most: load steps + 1, sweep "
                             "points, adaptivity.steps + 1 (times the points); null when not "
                             "known (accuracy: the loop stops at a level it finds)"}})}}}};
  json time = {{"type", "string"}, {"format", "date-time"}};
  return {
      {"type", "object"},
      {"additionalProperties", false},
      {"required",
       {"id", "name", "state", "created_at", "started_at", "finished_at", "attempts",
        "cancel_requested", "progress", "error", "converged", "stop_reason", "links"}},
      {"properties",
       {{"id", {{"type", "integer"}, {"minimum", 1}}},
        {"name", string_field("the case's name")},
        {"state", {{"enum", {"queued", "running", "succeeded", "failed", "cancelled"}}}},
        {"created_at", time},
        {"started_at", nullable(time)},
        {"finished_at", nullable(time)},
        {"attempts", {{"type", "integer"}, {"minimum", 0}}},
        {"cancel_requested", {{"type", "boolean"}}},
        {"progress", nullable(progress)},
        {"error", nullable(string_field("why it failed, with JSON pointers for case problems"))},
        {"converged", nullable({{"type", "boolean"},
                                {"description",
                                 "the result's converged; null until a result is stored. A job can "
                                 "succeed without converging unless the service runs with "
                                 "--fail-unconverged. A cancelled job with load steps keeps the "
                                 "steps solved before the cancel as its result (false, "
                                 "stop_reason cancelled)"}})},
        {"stop_reason", nullable({{"$ref", openapi::kResultSchema + "#/properties/stop_reason"}})},
        {"links", links}}}};
}

std::int64_t now_unix_ms() {
  using namespace std::chrono;
  return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

std::string format_rfc3339(std::int64_t unix_ms) {
  std::time_t seconds = static_cast<std::time_t>(unix_ms / 1000);
  int millis = static_cast<int>(unix_ms % 1000);
  if (millis < 0) {
    millis += 1000;
    seconds -= 1;
  }
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900,
                tm.tm_mon + 1, tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, millis);
  return buf;
}

}  // namespace fosls::service
