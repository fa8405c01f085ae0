#include "http_api.hpp"

#include <charconv>
#include <chrono>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>

#include "api_routes.hpp"
#include "openapi.hpp"
#include "problem.hpp"
#include "problem_catalogue.hpp"
#include "request_checks.hpp"
#include "static_files.hpp"
#include "stored_body.hpp"
#include "submission.hpp"

namespace fosls::service {

namespace {

using Clock = std::chrono::steady_clock;
using HandlerResponse = httplib::Server::HandlerResponse;

// Each request is handled start to finish on one httplib thread, so its start time can live
// in a thread_local between the pre-routing handler and the logger.
thread_local std::optional<Clock::time_point> request_start;

std::string dump(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// Succeeded jobs have a result; so have failed ones whose solve did not converge under
/// --fail-unconverged (kept to look at). Other failed jobs have none.
bool has_result(const Job& job) {
  // A failed or cancelled job has one when it stored one: not converged, or load steps kept.
  return job.state == JobState::kSucceeded ||
         ((job.state == JobState::kFailed || job.state == JobState::kCancelled) &&
          job.convergence.converged.has_value());
}

std::string method_label(const std::string& method) {
  for (const char* known : {"GET", "HEAD", "POST", "PUT", "PATCH", "DELETE", "OPTIONS"}) {
    if (method == known) return method;
  }
  return "other";
}

/// 400 for a Content-Length that is not one non-negative decimal integer: cpp-httplib would
/// read "abc" as 0 and leave the body on the connection as the next request.
std::optional<Problem> content_length_problem(const httplib::Request& req) {
  const std::size_t count = req.get_header_value_count("Content-Length");
  if (count == 0) return std::nullopt;
  const std::string value = req.get_header_value("Content-Length");
  std::string why;
  if (value.empty() || value.size() > 19 ||
      value.find_first_not_of("0123456789") != std::string::npos)
    why =
        "Content-Length must be a non-negative decimal integer, got '" + value.substr(0, 40) + "'";
  for (std::size_t i = 1; why.empty() && i < count; ++i)
    if (req.get_header_value("Content-Length", i) != value)
      why = "the request has several Content-Length headers with different values";
  if (why.empty()) return std::nullopt;
  return problems::invalid_content_length(why);
}

}  // namespace

HttpApi::HttpApi(JobStore& store, WorkerPool& workers, CaseValidator validator, Metrics& metrics,
                 EventLog& log, HttpApiOptions options)
    : store_(store),
      workers_(workers),
      validator_(std::move(validator)),
      metrics_(metrics),
      log_(log),
      options_(std::move(options)) {
  if (options_.admission_threads > 0)
    admission_ = std::make_unique<AdmissionPool>(options_.admission_threads,
                                                 options_.max_admissions_waiting);
}

std::string HttpApi::route_template(const std::string& path) {
  if (std::string route = matching_template(path); !route.empty()) return route;
  if (path.compare(0, 4, "/v1/") == 0) return "unknown";
  return "static";
}

std::function<void(const httplib::Request&, httplib::Response&)> HttpApi::handler(
    const ApiRoute& route) {
  if (const auto* plain = std::get_if<ApiRoute::PlainHandler>(&route.handler))
    return [this, h = *plain](const Request& req, Response& res) { (this->*h)(req, res); };
  return [this, h = std::get<ApiRoute::JobHandler>(route.handler), pattern = route.path](
             const Request& req, Response& res) {
    const std::string text = id_segment(pattern, req.path);
    if (auto id = parse_job_id(text)) {
      (this->*h)(req, res, *id);
    } else {
      send_problem(
          req, res,
          problems::not_found("there is no job '" + text + "' (job ids are positive integers)"));
    }
  };
}

void HttpApi::install(BoundedHttpServer& server) {
  server.set_payload_max_length(options_.max_body_bytes);
  // httplib writes headers and body separately; with Nagle's algorithm the body waits for the
  // client's delayed ACK on every keep-alive response (docs/service.md, "HTTP limits").
  server.set_tcp_nodelay(true);
  server.set_pre_routing_handler(
      [this](const Request& req, Response& res) { return pre_route(req, res); });
  server.set_expect_100_continue_handler(
      [this](const Request& req, Response& res) { return expect_continue(req, res); });
  server.set_error_handler(httplib::Server::HandlerWithResponse(
      [this](const Request& req, Response& res) { return on_error(req, res); }));
  server.set_exception_handler([this](const Request& req, Response& res, std::exception_ptr e) {
    on_exception(req, res, e);
  });
  server.set_logger([this](const Request& req, const Response& res) { on_logged(req, res); });
  server.set_head_refusal_handler([this](const Request& req, const HeadRejection& rejection,
                                         Response& res) { on_refused_head(req, rejection, res); });

  // Built once: they depend only on the program (the rules tables), not on the request.
  contract_ = {{"/v1/openapi.json", dump(openapi_document())}};
  for (const char* name : {"case.json", "case3d.json", "result.json", "result3d.json"})
    contract_["/v1/schemas/" + std::string(name)] = dump(*published_schema(name));
  for (const ApiRoute& route : api_routes()) {
    const std::string pattern = route_pattern(route.path);
    auto h = handler(route);
    if (route.method == "GET")
      server.Get(pattern, std::move(h));
    else if (route.method == "POST")
      server.Post(pattern, std::move(h));
    else if (route.method == "DELETE")
      server.Delete(pattern, std::move(h));
    else
      throw std::logic_error("unsupported method in the route table: " + std::string(route.method));
  }
  // Last, so API routes win: everything else under / comes from --web-root.
  server.Get("/.*", [this](const Request& req, Response& res) { static_file(req, res); });
}

HandlerResponse HttpApi::pre_route(const Request& req, Response& res) {
  request_start = Clock::now();
  // cpp-httplib 0.11.4 reads chunked bodies without applying the payload limit.
  if (req.has_header("Transfer-Encoding")) {
    res.set_header("Connection", "close");
    send_problem(
        req, res,
        problems::length_required(is_chunked(req.get_header_value("Transfer-Encoding"))
                                      ? "chunked request bodies are not accepted; send the "
                                        "body with a Content-Length header"
                                      : "Transfer-Encoding is not supported; send the body "
                                        "with a Content-Length header"));
    return HandlerResponse::Handled;
  }
  if (auto p = content_length_problem(req)) {
    res.set_header("Connection", "close");  // the body's bytes must not be read as a request
    send_problem(req, res, *p);
    return HandlerResponse::Handled;
  }
  if (method_not_served(req, res)) return HandlerResponse::Handled;
  const bool body_method = req.method == "POST" || req.method == "PUT" || req.method == "PATCH" ||
                           req.method == "DELETE";
  if (!body_method || req.has_header("Content-Length")) return HandlerResponse::Unhandled;

  // Without Content-Length cpp-httplib would read the body until the client closes the
  // connection. Routes that take no body are served here without reading anything.
  const std::string route = matching_template(req.path);
  for (const ApiRoute& r : api_routes()) {
    // Only POST /v1/jobs takes a body; the others (cancel, delete) need none.
    if (r.path != route || r.method != req.method || route == "/v1/jobs") continue;
    handler(r)(req, res);
    return HandlerResponse::Handled;
  }
  if (req.path == "/v1/jobs" && req.method == "POST") {
    send_problem(req, res, problems::length_required("send the case with a Content-Length header"));
    return HandlerResponse::Handled;
  }
  res.status = 404;  // on_error fills in the problem (or turns it into 405)
  return HandlerResponse::Handled;
}

bool HttpApi::method_not_served(const Request& req, Response& res) {
  // Routes are GET (HEAD), POST and DELETE; cpp-httplib answers TRACE and CONNECT with a bare
  // 400 and PUT, PATCH, OPTIONS through its 404. The method is wrong, not the request: 405 with
  // what the path allows (an API route's methods, GET and HEAD for files), 404 for unknown API
  // paths.
  for (const char* served : {"GET", "HEAD", "POST", "DELETE"})
    if (req.method == served) return false;
  std::string allowed = allowed_methods(req.path);
  if (allowed.empty() && req.path.compare(0, 4, "/v1/") != 0) allowed = "GET, HEAD";
  // A body it may carry is not read: what follows on the connection is not a request.
  if (req.get_header_value("Content-Length", 0) != "" &&
      req.get_header_value("Content-Length") != "0")
    res.set_header("Connection", "close");
  if (allowed.empty()) {
    send_problem(req, res, problems::not_found("there is nothing at " + req.path));
  } else {
    res.set_header("Allow", allowed);
    send_problem(req, res, problems::method_not_allowed(req.method, req.path, allowed));
  }
  return true;
}

int HttpApi::expect_continue(const Request& req, Response& res) {
  request_start = Clock::now();
  // Refuse before the client sends a body that would be discarded anyway.
  if (req.method == "POST" && req.path == "/v1/jobs") {
    if (req.has_header("Transfer-Encoding")) {
      send_problem(req, res,
                   problems::length_required("send the body with a Content-Length header"));
      return res.status;
    }
    const std::string length = req.get_header_value("Content-Length");
    std::size_t n = 0;
    auto [end, ec] = std::from_chars(length.data(), length.data() + length.size(), n);
    if (ec == std::errc::result_out_of_range ||
        (ec == std::errc() && n > options_.max_body_bytes)) {
      send_problem(req, res, problems::payload_too_large(options_.max_body_bytes));
      return res.status;
    }
    if (!is_json_media_type(req.get_header_value("Content-Type"))) {
      send_problem(req, res,
                   problems::unsupported_media_type(req.get_header_value("Content-Type")));
      return res.status;
    }
  }
  return 100;
}

HandlerResponse HttpApi::on_error(const Request& req, Response& res) {
  // Always "Handled": in cpp-httplib 0.11.4 only then does a response written outside routing
  // (e.g. a refused Expect: 100-continue) get its Content-Length header.
  if (!res.body.empty()) return HandlerResponse::Handled;  // a handler wrote the problem
  Problem p;
  p.status = res.status;
  if (res.status == 404) {
    const std::string allowed = allowed_methods(req.path);
    if (!allowed.empty()) {
      p = problems::method_not_allowed(req.method, req.path, allowed);
      res.set_header("Allow", allowed);
    } else {
      p = problems::not_found("there is nothing at " + req.path);
    }
  } else if (res.status == 413) {
    p = problems::payload_too_large(options_.max_body_bytes);
  } else if (res.status == 400) {
    // What follows a request cpp-httplib could not parse or read is not a request.
    res.set_header("Connection", "close");
    p = problems::bad_request("the HTTP request is malformed or its body could not be read");
  } else if (res.status == 414) {
    p = problems::uri_too_long();
  }
  send_problem(req, res, p);
  return HandlerResponse::Handled;
}

void HttpApi::on_refused_head(const Request& req, const HeadRejection& rejection, Response& res) {
  send_problem(req, res, problems::refused_request_head(rejection.status, rejection.detail));
  on_logged(req, res);
}

void HttpApi::on_exception(const Request& req, Response& res, std::exception_ptr error) {
  Problem p;
  try {
    std::rethrow_exception(error);
  } catch (const StoreFullError& e) {
    p = problems::store_full(507, e.what());
    res.set_header("Retry-After", std::to_string(options_.retry_after_seconds));
    log_.write("store_full", {{"path", req.path}, {"error", e.what()}});
  } catch (const StoreError& e) {
    p = problems::store_unavailable();
    res.set_header("Retry-After", std::to_string(options_.retry_after_seconds));
    log_.write("store_error", {{"path", req.path}, {"error", e.what()}});
  } catch (const std::exception& e) {
    p = problems::internal_error();
    log_.write("internal_error", {{"path", req.path}, {"error", e.what()}});
  } catch (...) {
    p = problems::internal_error();
    log_.write("internal_error", {{"path", req.path}, {"error", "unknown exception"}});
  }
  send_problem(req, res, p);
}

void HttpApi::on_logged(const Request& req, const Response& res) {
  std::optional<double> seconds;
  if (request_start) {
    seconds = std::chrono::duration<double>(Clock::now() - *request_start).count();
    request_start.reset();
  }
  metrics_.record_http(method_label(req.method), route_template(req.path), res.status,
                       seconds.value_or(0.0));
  log_.write("http_request",
             {{"method", req.method},
              {"path", req.path},
              {"status", res.status},
              {"duration_ms", seconds ? nlohmann::json(*seconds * 1e3) : nlohmann::json(nullptr)},
              {"remote", req.remote_addr}});
}

void HttpApi::not_found(const Request& req, Response& res, std::int64_t id) {
  send_problem(req, res, problems::job_not_found(id));
}

void HttpApi::send_job(Response& res, int status, const Job& job) {
  res.status = status;
  res.set_content(dump(job_to_json(job)), "application/json");
}

void HttpApi::post_job(const Request& req, Response& res) {
  const std::string content_type = req.get_header_value("Content-Type");
  if (!is_json_media_type(content_type)) {
    send_problem(req, res, problems::unsupported_media_type(content_type));
    return;
  }
  std::optional<std::string> key;
  if (req.has_header("Idempotency-Key")) {
    key = req.get_header_value("Idempotency-Key");
    if (!is_valid_idempotency_key(*key)) {
      send_problem(req, res, problems::invalid_idempotency_key());
      return;
    }
  }
  std::variant<Problem, NewJob> read;
  const std::function<void()> work = [&] {
    read = read_submission(req.body, validator_, options_.max_json_depth);
  };
  // A large body is read on the admission pool's low-priority threads, this one waiting.
  if (admission_ && req.body.size() >= options_.large_body_bytes) {
    if (!admission_->run(work)) {
      res.set_header("Retry-After", std::to_string(options_.retry_after_seconds));
      return send_problem(req, res, problems::admission_busy());
    }
  } else {
    work();
  }
  if (const auto* problem = std::get_if<Problem>(&read)) return send_problem(req, res, *problem);
  NewJob job = std::move(std::get<NewJob>(read));
  job.idempotency_key = key;
  SubmitOutcome outcome = store_.submit(job, options_.max_queue);
  switch (outcome.kind) {
    case SubmitOutcome::Kind::kCreated:
      res.set_header("Location", "/v1/jobs/" + std::to_string(outcome.job->id));
      send_job(res, 202, *outcome.job);
      log_.write("job_transition", {{"job_id", outcome.job->id},
                                    {"from", nullptr},
                                    {"to", "queued"},
                                    {"name", outcome.job->name}});
      workers_.notify_job_available();
      return;
    case SubmitOutcome::Kind::kReplayed:
      res.set_header("Location", "/v1/jobs/" + std::to_string(outcome.job->id));
      send_job(res, 200, *outcome.job);
      return;
    case SubmitOutcome::Kind::kKeyConflict:
      send_problem(req, res, problems::idempotency_key_reused(outcome.job->id));
      return;
    case SubmitOutcome::Kind::kQueueFull:
      res.set_header("Retry-After", std::to_string(options_.retry_after_seconds));
      send_problem(req, res, problems::queue_full(options_.max_queue));
      return;
  }
}

void HttpApi::list_jobs(const Request& req, Response& res) {
  // A parameter given twice has no one meaning (cpp-httplib would take the first silently).
  for (auto it = req.params.begin(); it != req.params.end();
       it = req.params.upper_bound(it->first)) {
    if (const auto n = req.params.count(it->first); n > 1)
      return send_problem(req, res,
                          problems::invalid_parameter(
                              it->first, "given " + std::to_string(n) + " times; give it once"));
  }
  JobListQuery query;
  if (req.has_param("state")) {
    const std::string state = req.get_param_value("state");
    query.state = parse_job_state(state);
    if (!query.state) {
      send_problem(req, res,
                   problems::invalid_parameter(
                       "state", "'" + state +
                                    "' is not a state; use queued, running, succeeded, "
                                    "failed or cancelled"));
      return;
    }
  }
  if (req.has_param("converged")) {
    const std::string text = req.get_param_value("converged");
    if (text != "true" && text != "false") {
      send_problem(req, res,
                   problems::invalid_parameter("converged", "'" + text + "' is not true or false"));
      return;
    }
    query.converged = text == "true";
  }
  if (req.has_param("page_size")) {
    const std::string text = req.get_param_value("page_size");
    int n = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || end != text.data() + text.size() || n < 1 || n > 100) {
      send_problem(req, res,
                   problems::invalid_parameter("page_size", "must be an integer from 1 to 100"));
      return;
    }
    query.page_size = n;
  }
  if (req.has_param("page_token") && !req.get_param_value("page_token").empty()) {
    query.before_id = parse_job_id(req.get_param_value("page_token"));
    if (!query.before_id) {
      send_problem(req, res,
                   problems::invalid_parameter(
                       "page_token", "not a token from next_page_token of an earlier page"));
      return;
    }
  }
  JobPage page = store_.list(query);
  nlohmann::json jobs = nlohmann::json::array();
  for (const Job& job : page.jobs) jobs.push_back(job_to_json(job));
  nlohmann::json body = {{"jobs", std::move(jobs)}};
  body["next_page_token"] = page.next_before_id
                                ? nlohmann::json(std::to_string(*page.next_before_id))
                                : nlohmann::json(nullptr);
  res.set_content(dump(body), "application/json");
}

void HttpApi::get_job(const Request& req, Response& res, std::int64_t id) {
  auto job = store_.find(id);
  if (!job) return not_found(req, res, id);
  send_job(res, 200, *job);
}

void HttpApi::get_result(const Request& req, Response& res, std::int64_t id) {
  auto job = store_.find(id);
  if (!job) return not_found(req, res, id);
  if (has_result(*job)) {
    if (const auto bytes = store_.result_json_size(id)) {
      set_stored_result_body(res, store_, id, *bytes);
      return;
    }
  }
  send_problem(req, res, problems::job_without_result(*job));
}

void HttpApi::get_solution(const Request& req, Response& res, std::int64_t id) {
  auto job = store_.find(id);
  if (!job) return not_found(req, res, id);
  if (has_result(*job)) {
    if (const auto stored = store_.stored_vtu(id)) {
      res.set_header("Content-Disposition",
                     "attachment; filename=\"job-" + std::to_string(id) + ".vtu\"");
      set_stored_vtu_body(req, res, store_, id, *stored, "application/xml");
      return;
    }
  }
  send_problem(req, res, problems::job_without_result(*job));
}

void HttpApi::get_case(const Request& req, Response& res, std::int64_t id) {
  auto text = store_.case_json(id);
  if (!text) return not_found(req, res, id);
  res.set_content(*text, "application/json");
}

void HttpApi::cancel_job(const Request& req, Response& res, std::int64_t id) {
  CancelOutcome outcome = store_.cancel(id);
  switch (outcome.kind) {
    case CancelOutcome::Kind::kNotFound:
      return not_found(req, res, id);
    case CancelOutcome::Kind::kCancelled:
      log_.write("job_transition", {{"job_id", id}, {"from", "queued"}, {"to", "cancelled"}});
      return send_job(res, 200, *outcome.job);
    case CancelOutcome::Kind::kRequested:
      workers_.request_cancel(id);
      log_.write("job_cancel_requested", {{"job_id", id}});
      return send_job(res, 202, *outcome.job);
    case CancelOutcome::Kind::kAlreadyFinished:
      return send_problem(req, res, problems::job_finished(id, outcome.job->state));
  }
}

void HttpApi::delete_job(const Request& req, Response& res, std::int64_t id) {
  switch (store_.remove(id)) {
    case DeleteOutcome::kNotFound:
      return not_found(req, res, id);
    case DeleteOutcome::kDeleted:
      log_.write("job_deleted", {{"job_id", id}});
      res.status = 204;
      return;
    case DeleteOutcome::kNotFinished:
      return send_problem(req, res, problems::job_not_finished(id));
  }
}

void HttpApi::get_contract(const Request& req, Response& res) {
  res.set_content(contract_.at(req.path), "application/json");
}

void HttpApi::healthz(const Request& req, Response& res) {
  // Throws StoreError when the store does not answer → 503 through on_exception. A full disk
  // can also stop a new connection from opening (SQLite extends its shared-memory file).
  StoreHealth health;
  try {
    health = store_.health();
  } catch (const StoreFullError& e) {
    health = {true, e.what()};
  }
  if (health.disk_full) {
    res.set_header("Retry-After", std::to_string(options_.retry_after_seconds));
    return send_problem(req, res, problems::store_full(503, health.detail));
  }
  res.set_content(dump({{"status", "ok"}, {"workers", workers_.size()}, {"busy", workers_.busy()}}),
                  "application/json");
}

void HttpApi::metrics(const Request& req, Response& res) {
  MetricsSnapshot snapshot;
  snapshot.jobs_by_state = store_.count_by_state();
  snapshot.not_converged = store_.count_not_converged();
  snapshot.workers = workers_.size();
  snapshot.busy_workers = workers_.busy();
  res.set_content(metrics_.render(snapshot), "text/plain; version=0.0.4; charset=utf-8");
}

void HttpApi::static_file(const Request& req, Response& res) {
  // A GET (or HEAD) that reaches here on an API route's path is a method that route lacks
  // (GET /v1/jobs/1/cancel): 405 with Allow, as every other method gets in on_error.
  if (const std::string allowed = allowed_methods(req.path); !allowed.empty()) {
    res.set_header("Allow", allowed);
    return send_problem(req, res, problems::method_not_allowed(req.method, req.path, allowed));
  }
  std::optional<std::filesystem::path> file;
  if (!options_.web_root.empty()) file = resolve_static_file(options_.web_root, req.path);
  std::string content;
  if (file) {
    std::ifstream in(*file, std::ios::binary);
    if (in) content.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in || in.bad()) file.reset();
  }
  if (!file) return send_problem(req, res, problems::not_found("there is nothing at " + req.path));
  res.set_header("Cache-Control", "no-cache");
  res.set_content(content, std::string(content_type_for(*file)));
}

}  // namespace fosls::service
