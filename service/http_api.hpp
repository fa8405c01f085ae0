#pragma once
// The REST API of the job service (docs/service.md, "API") on a cpp-httplib server:
// routes, body limits, problem+json errors, request logging and metrics.

#include <httplib.h>

#include <cstddef>
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "admission_pool.hpp"
#include "api_routes.hpp"
#include "bounded_http_server.hpp"
#include "case/format/case_error.hpp"
#include "event_log.hpp"
#include "job_store.hpp"
#include "metrics.hpp"
#include "submission.hpp"
#include "worker_pool.hpp"

namespace fosls::service {

struct HttpApiOptions {
  std::size_t max_body_bytes = 8u << 20;  ///< larger POST bodies get 413
  std::size_t max_queue = 1000;           ///< queued jobs beyond which POST gets 503
  std::filesystem::path web_root;         ///< served at / (empty: no static files)
  int retry_after_seconds = 5;            ///< Retry-After of 503 responses
  int max_json_depth = 64;                ///< deeper nesting is refused before parsing
  /// Bodies from this size on are read on the admission pool (admission_pool.hpp).
  std::size_t large_body_bytes = 256u << 10;
  /// Threads of the admission pool (0: large bodies are read on the HTTP threads too).
  int admission_threads = 2;
  /// Large submissions waiting for the pool beyond which POST answers 503.
  std::size_t max_admissions_waiting = 256;
};

/// Installs the API on a BoundedHttpServer. Handlers only touch the store and wake workers;
/// they never solve.
class HttpApi {
 public:
  /// All references must outlive the server the API is installed on.
  HttpApi(JobStore& store, WorkerPool& workers, CaseValidator validator, Metrics& metrics,
          EventLog& log, HttpApiOptions options);

  /// Registers routes and handlers, and sets the payload limit on `server`.
  void install(BoundedHttpServer& server);

  /// The route template of a path for metrics labels ("/v1/jobs/{id}/result", "static").
  static std::string route_template(const std::string& path);

 private:
  friend std::span<const ApiRoute> api_routes();  // the route table names the handlers
  using Request = httplib::Request;
  using Response = httplib::Response;

  void post_job(const Request& req, Response& res);
  void list_jobs(const Request& req, Response& res);
  void get_job(const Request& req, Response& res, std::int64_t id);
  void get_result(const Request& req, Response& res, std::int64_t id);
  void get_solution(const Request& req, Response& res, std::int64_t id);
  void get_case(const Request& req, Response& res, std::int64_t id);
  void cancel_job(const Request& req, Response& res, std::int64_t id);
  void delete_job(const Request& req, Response& res, std::int64_t id);
  void get_contract(const Request& req, Response& res);
  void healthz(const Request& req, Response& res);
  void metrics(const Request& req, Response& res);
  void static_file(const Request& req, Response& res);

  httplib::Server::HandlerResponse pre_route(const Request& req, Response& res);
  int expect_continue(const Request& req, Response& res);
  /// Answers a method no route has (TRACE, CONNECT, PUT, …) with 405; false for the others.
  bool method_not_served(const Request& req, Response& res);
  httplib::Server::HandlerResponse on_error(const Request& req, Response& res);
  void on_refused_head(const Request& req, const HeadRejection& rejection, Response& res);
  void on_exception(const Request& req, Response& res, std::exception_ptr error);
  void on_logged(const Request& req, const Response& res);

  /// The handler of a route of api_routes() as httplib calls it (job ids parsed first).
  std::function<void(const Request&, Response&)> handler(const ApiRoute& route);

  /// 404 problem for an unknown job id.
  void not_found(const Request& req, Response& res, std::int64_t id);
  /// Sends a job JSON with `status`.
  void send_job(Response& res, int status, const Job& job);

  JobStore& store_;
  WorkerPool& workers_;
  CaseValidator validator_;
  Metrics& metrics_;
  EventLog& log_;
  HttpApiOptions options_;
  std::unique_ptr<AdmissionPool> admission_;  ///< null when admission_threads is 0
  /// The OpenAPI document and the JSON Schemas, by path (built in install()).
  std::map<std::string, std::string> contract_;
};

}  // namespace fosls::service
