// The HTTP layer in-process over a real SQLite store, with a fake validator and solver step:
// every status code of the API, problem+json bodies, limits, idempotency, static files, logs.

#include "http_api.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <chrono>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <thread>

#include "api_routes.hpp"
#include "disk_full_store.hpp"
#include "fake_job_runner.hpp"
#include "http_client.hpp"
#include "openapi.hpp"
#include "sqlite_job_store.hpp"
#include "temp_dir.hpp"

namespace fosls::service {
namespace {

using nlohmann::json;
using testing::fake_job_runner;
using testing::raw_body;
using testing::raw_http;
using testing::TempDir;

/// Test double for validate_case: objects are valid unless they carry "bad"; a valid case is
/// estimated at 1.5 s.
CaseVerdict fake_validator(const json& j) {
  CaseVerdict verdict;
  if (!j.is_object()) {
    verdict.errors.push_back({"", "the case must be a JSON object"});
  } else if (j.contains("bad")) {
    verdict.errors.push_back({"/bad", "remove this field"});
    verdict.errors.push_back({"/material/nu", "must be in [0, 0.5]"});
  } else {
    verdict.estimate_seconds = 1.5;
  }
  return verdict;
}

/// A complete service (store, workers, API, server) on a free loopback port.
class Service {
 public:
  explicit Service(HttpApiOptions api_options = {}, bool start_workers = true)
      : store_(dir_.file("jobs.db")),
        pool_(store_, fake_job_runner, log_, metrics_, pool_options()),
        api_(store_, pool_, fake_validator, metrics_, log_, with_web_root(api_options)) {
    std::ofstream(dir_.path() / "web" / "index.html") << "<html>fosls</html>";
    std::ofstream(dir_.path() / "web" / "app.js") << "console.log(1)";
    std::ofstream(dir_.path() / "secret.txt") << "outside the web root";
    server_.new_task_queue = [] { return new httplib::ThreadPool(4); };
    api_.install(server_);
    port_ = server_.bind_to_any_port("127.0.0.1");
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (start_workers) pool_.start();
  }
  ~Service() {
    pool_.begin_shutdown();
    server_.stop();
    thread_.join();
    pool_.join();
  }

  int port() const { return port_; }
  httplib::Client client() const { return httplib::Client("127.0.0.1", port_); }
  SqliteJobStore& store() { return store_; }
  WorkerPool& pool() { return pool_; }
  /// The log so far (a file: server threads may be writing while the test reads).
  std::string log() const {
    std::ifstream in(dir_.file("service.log"));
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

  json wait_state(std::int64_t id, const std::string& state) {
    auto cli = client();
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    for (;;) {
      auto res = cli.Get("/v1/jobs/" + std::to_string(id));
      if (res && res->status == 200) {
        json job = json::parse(res->body);
        if (job["state"] == state) return job;
      }
      if (std::chrono::steady_clock::now() > give_up) {
        ADD_FAILURE() << "job " << id << " never became " << state;
        return json();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }

 private:
  static WorkerPoolOptions pool_options() {
    WorkerPoolOptions o;
    o.workers = 1;
    o.idle_poll = std::chrono::milliseconds(50);
    return o;
  }
  HttpApiOptions with_web_root(HttpApiOptions o) {
    std::filesystem::create_directories(dir_.path() / "web");
    o.web_root = dir_.path() / "web";
    return o;
  }

  TempDir dir_;
  std::ofstream log_file_{dir_.file("service.log")};
  EventLog log_{log_file_};
  Metrics metrics_;
  SqliteJobStore store_;
  WorkerPool pool_;
  HttpApi api_;
  BoundedHttpServer server_;
  int port_ = 0;
  std::thread thread_;
};

httplib::Result post_json(httplib::Client& cli, const std::string& path, const std::string& body,
                          const httplib::Headers& headers = {}) {
  return cli.Post(path.c_str(), headers, body, "application/json");
}

void expect_problem(const httplib::Result& res, int status, const std::string& type_suffix = "") {
  ASSERT_TRUE(res) << "no response";
  EXPECT_EQ(res->status, status) << res->body;
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/problem+json");
  json p = json::parse(res->body, nullptr, false);
  ASSERT_FALSE(p.is_discarded()) << res->body;
  EXPECT_EQ(p["status"], status);
  EXPECT_TRUE(p["title"].is_string() && !p["title"].get<std::string>().empty());
  EXPECT_TRUE(p["detail"].is_string() && !p["detail"].get<std::string>().empty());
  EXPECT_TRUE(p["type"].is_string());
  if (!type_suffix.empty()) {
    EXPECT_EQ(p["type"], "urn:fosls:problem:" + type_suffix);
  }
}

TEST(HttpApi, PostPollAndFetchResult) {
  Service svc;
  auto cli = svc.client();
  auto res = post_json(cli, "/v1/jobs", R"({"name":"demo","mode":"ok","iterations":3})");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 202) << res->body;
  const json job = json::parse(res->body);
  const std::string location = res->get_header_value("Location");
  EXPECT_EQ(location, "/v1/jobs/" + std::to_string(job["id"].get<std::int64_t>()));
  EXPECT_EQ(job["name"], "demo");
  EXPECT_EQ(job["state"], "queued");
  EXPECT_EQ(job["attempts"], 0);
  EXPECT_TRUE(job["started_at"].is_null());
  EXPECT_EQ(job["created_at"].get<std::string>().back(), 'Z');

  const json done = svc.wait_state(job["id"], "succeeded");
  EXPECT_EQ(done["attempts"], 1);
  EXPECT_EQ(done["progress"]["iteration"], 3);
  EXPECT_TRUE(done["finished_at"].is_string());

  auto result = cli.Get((location + "/result").c_str());
  ASSERT_EQ(result->status, 200);
  EXPECT_EQ(result->get_header_value("Content-Type"), "application/json");
  EXPECT_EQ(json::parse(result->body)["echo"]["name"], "demo");
  auto vtu = cli.Get((location + "/solution.vtu").c_str());
  ASSERT_EQ(vtu->status, 200);
  EXPECT_EQ(vtu->get_header_value("Content-Type"), "application/xml");
  EXPECT_NE(vtu->body.find("UnstructuredGrid"), std::string::npos);

  // Finished: cancel is a conflict, delete works once.
  expect_problem(cli.Post((location + "/cancel").c_str()), 409, "job-finished");
  auto del = cli.Delete(location.c_str());
  EXPECT_EQ(del->status, 204);
  expect_problem(cli.Get(location.c_str()), 404, "job-not-found");
}

TEST(HttpApi, BodyErrors) {
  HttpApiOptions options;
  options.max_body_bytes = 4096;
  Service svc(options, false);
  auto cli = svc.client();
  // curl -d sends a form content type.
  expect_problem(cli.Post("/v1/jobs", "{}", "application/x-www-form-urlencoded"), 415,
                 "unsupported-media-type");
  expect_problem(cli.Post("/v1/jobs", "{}", "text/plain"), 415);
  expect_problem(post_json(cli, "/v1/jobs", "{\"name\": "), 400, "unparsable-json");
  expect_problem(post_json(cli, "/v1/jobs", "{\"size\": 1e999}"), 400, "unparsable-json");
  expect_problem(post_json(cli, "/v1/jobs", std::string(100, '[') + std::string(100, ']')), 400,
                 "unparsable-json");
  expect_problem(post_json(cli, "/v1/jobs", "{\"pad\":\"" + std::string(5000, 'x') + "\"}"), 413);

  auto invalid = post_json(cli, "/v1/jobs", R"({"bad":1})");
  expect_problem(invalid, 422, "invalid-case");
  const json p = json::parse(invalid->body);
  ASSERT_EQ(p["errors"].size(), 2u);
  EXPECT_EQ(p["errors"][0]["pointer"], "/bad");
  EXPECT_EQ(p["errors"][1]["pointer"], "/material/nu");
  EXPECT_TRUE(p["errors"][1]["detail"].is_string());
  expect_problem(post_json(cli, "/v1/jobs", "[1,2]"), 422, "invalid-case");
  EXPECT_EQ(svc.store().count_by_state()[JobState::kQueued], 0);  // nothing was queued
}

TEST(HttpApi, ChunkedAndLengthlessBodiesAreRefusedWithoutReading) {
  Service svc({}, false);
  auto chunked = raw_http(svc.port(),
                          "POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                          "Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n"
                          "2\r\n{}\r\n0\r\n\r\n");
  EXPECT_EQ(chunked.status, 411) << chunked.text;
  EXPECT_NE(chunked.text.find("application/problem+json"), std::string::npos);
  EXPECT_NE(raw_body(chunked).find("chunked"), std::string::npos);

  auto lengthless =
      raw_http(svc.port(),
               "POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
               "Connection: close\r\n\r\n");
  EXPECT_EQ(lengthless.status, 411) << lengthless.text;

  // Expect: 100-continue with a body over the limit: refused before the body is sent.
  auto expect = raw_http(svc.port(),
                         "POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                         "Content-Length: 999999999\r\nExpect: 100-continue\r\n"
                         "Connection: close\r\n\r\n");
  EXPECT_EQ(expect.status, 413) << expect.text;
  // Without it, clients wait for the connection to close to know where the body ends.
  EXPECT_NE(expect.text.find("Content-Length:"), std::string::npos) << expect.text;
  EXPECT_EQ(svc.store().count_by_state()[JobState::kQueued], 0);
}

TEST(HttpApi, DuplicateKeysAreRefusedWithTheirPointer) {
  Service svc({}, false);
  auto cli = svc.client();
  const std::pair<const char*, const char*> cases[] = {
      {R"({"name": "a", "name": "b"})", "/name"},
      {R"({"mesh": {"size": 1, "refinements": 2, "size": 2}})", "/mesh/size"},
      {R"({"boundary": {"top": {"values": [{"x": 1}, {"x": 1, "x": 2}]}}})",
       "/boundary/top/values/1/x"},
      {R"({"a/b~c": [1, [2, 3], {"k": 0}], "a/b~c": 1})", "/a~1b~0c"},
  };
  for (const auto& [body, pointer] : cases) {
    auto res = post_json(cli, "/v1/jobs", body);
    expect_problem(res, 422, "invalid-case");
    const json p = json::parse(res->body);
    ASSERT_EQ(p["errors"].size(), 1u) << res->body;
    EXPECT_EQ(p["errors"][0]["pointer"], pointer) << body;
    EXPECT_NE(p["errors"][0]["detail"].get<std::string>().find("twice"), std::string::npos);
  }
  EXPECT_EQ(svc.store().count_by_state()[JobState::kQueued], 0);
}

TEST(HttpApi, MalformedOrNegativeContentLengthIs400AndItsBodyIsNeverARequest) {
  Service svc({}, false);
  for (const char* length : {"abc", "-5", "12x", "1e3", "99999999999999999999"}) {
    // The bytes after the headers would otherwise be read as the next request.
    auto res = raw_http(svc.port(),
                        std::string("POST /v1/jobs HTTP/1.1\r\nHost: x\r\n"
                                    "Content-Type: application/json\r\nContent-Length: ") +
                            length + "\r\n\r\nGET /v1/jobs HTTP/1.1\r\nHost: x\r\n\r\n",
                        1);
    EXPECT_EQ(res.status, 400) << length << "\n" << res.text;
    EXPECT_NE(raw_body(res).find("invalid-content-length"), std::string::npos) << res.text;
    EXPECT_EQ(res.text.find("HTTP/1.1 200"), std::string::npos)
        << "the body was served as a request: " << res.text;
  }
  auto twice = raw_http(svc.port(),
                        "POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                        "Content-Length: 2\r\nContent-Length: 3\r\nConnection: close\r\n\r\n{}");
  EXPECT_EQ(twice.status, 400) << twice.text;
  EXPECT_EQ(svc.store().count_by_state()[JobState::kQueued], 0);
}

TEST(HttpApi, CancelAndDeleteWorkWithoutABody) {
  Service svc({}, false);
  auto cli = svc.client();
  const auto a = json::parse(post_json(cli, "/v1/jobs", R"({"n":1})")->body)["id"].get<int>();
  const auto b = json::parse(post_json(cli, "/v1/jobs", R"({"n":2})")->body)["id"].get<int>();
  // What `curl -X POST .../cancel` sends: no Content-Length at all.
  auto cancel =
      raw_http(svc.port(), "POST /v1/jobs/" + std::to_string(a) +
                               "/cancel HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(cancel.status, 200) << cancel.text;
  EXPECT_EQ(json::parse(raw_body(cancel))["state"], "cancelled");
  auto del = raw_http(svc.port(), "DELETE /v1/jobs/" + std::to_string(a) +
                                      " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(del.status, 204) << del.text;
  auto busy = raw_http(svc.port(), "DELETE /v1/jobs/" + std::to_string(b) +
                                       " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(busy.status, 409) << busy.text;
  // httplib's client sends Content-Length: 0.
  auto cancel_b = cli.Post(("/v1/jobs/" + std::to_string(b) + "/cancel").c_str());
  EXPECT_EQ(cancel_b->status, 200);
}

TEST(HttpApi, RunningJobs409UntilCancelledThenWorkerIsFree) {
  Service svc;
  auto cli = svc.client();
  const json job = json::parse(post_json(cli, "/v1/jobs", R"({"mode":"until_cancel"})")->body);
  const std::string path = "/v1/jobs/" + std::to_string(job["id"].get<int>());
  svc.wait_state(job["id"], "running");
  auto early = cli.Get((path + "/result").c_str());
  expect_problem(early, 409, "job-not-finished");
  EXPECT_EQ(json::parse(early->body)["state"], "running");
  expect_problem(cli.Get((path + "/solution.vtu").c_str()), 409);
  expect_problem(cli.Delete(path.c_str()), 409, "job-not-finished");

  auto cancel = cli.Post((path + "/cancel").c_str());
  ASSERT_EQ(cancel->status, 202);
  EXPECT_TRUE(json::parse(cancel->body)["cancel_requested"].get<bool>());
  svc.wait_state(job["id"], "cancelled");
  auto result = cli.Get((path + "/result").c_str());
  expect_problem(result, 409, "job-cancelled");

  const json next = json::parse(post_json(cli, "/v1/jobs", R"({"mode":"ok"})")->body);
  svc.wait_state(next["id"], "succeeded");  // the only worker is free again
}

TEST(HttpApi, FailedJobResultExplainsWhy) {
  Service svc;
  auto cli = svc.client();
  const json job = json::parse(post_json(cli, "/v1/jobs", R"({"mode":"fail"})")->body);
  const json failed = svc.wait_state(job["id"], "failed");
  EXPECT_EQ(failed["error"], "/solver/tolerance: fake failure");
  auto res = cli.Get(("/v1/jobs/" + std::to_string(job["id"].get<int>()) + "/result").c_str());
  expect_problem(res, 409, "job-failed");
  EXPECT_NE(json::parse(res->body)["detail"].get<std::string>().find("fake failure"),
            std::string::npos);
}

TEST(HttpApi, UnknownIdsRoutesAndMethods) {
  Service svc({}, false);
  auto cli = svc.client();
  expect_problem(cli.Get("/v1/jobs/12345"), 404, "job-not-found");
  expect_problem(cli.Get("/v1/jobs/12345/result"), 404);
  expect_problem(cli.Post("/v1/jobs/12345/cancel"), 404);
  expect_problem(cli.Delete("/v1/jobs/12345"), 404);
  expect_problem(cli.Get("/v1/jobs/abc"), 404);
  expect_problem(cli.Get("/v1/jobs/99999999999999999999999"), 404);
  expect_problem(cli.Get("/v1/nothing"), 404);
  auto wrong = cli.Put("/v1/jobs", "{}", "application/json");
  expect_problem(wrong, 405);
  EXPECT_EQ(wrong->get_header_value("Allow"), "GET, POST");
}

TEST(HttpApi, IdempotencyKey) {
  Service svc({}, false);
  auto cli = svc.client();
  const httplib::Headers key = {{"Idempotency-Key", "order-42"}};
  auto first = post_json(cli, "/v1/jobs", R"({"a":1,"b":2})", key);
  ASSERT_EQ(first->status, 202);
  // Same case with keys in another order and other spacing: the same body.
  auto again = post_json(cli, "/v1/jobs", R"({ "b": 2, "a": 1 })", key);
  ASSERT_EQ(again->status, 200);
  EXPECT_EQ(json::parse(again->body)["id"], json::parse(first->body)["id"]);
  EXPECT_EQ(again->get_header_value("Location"), first->get_header_value("Location"));
  auto conflict = post_json(cli, "/v1/jobs", R"({"a":2})", key);
  expect_problem(conflict, 422, "idempotency-key-reused");
  expect_problem(post_json(cli, "/v1/jobs", "{}", {{"Idempotency-Key", "has space"}}), 400,
                 "invalid-idempotency-key");
  EXPECT_EQ(svc.store().count_by_state()[JobState::kQueued], 1);
}

TEST(HttpApi, FullQueueAnswers503WithRetryAfter) {
  HttpApiOptions options;
  options.max_queue = 2;
  Service svc(options, false);
  auto cli = svc.client();
  EXPECT_EQ(post_json(cli, "/v1/jobs", "{\"n\":1}")->status, 202);
  EXPECT_EQ(post_json(cli, "/v1/jobs", "{\"n\":2}")->status, 202);
  auto full = post_json(cli, "/v1/jobs", "{\"n\":3}");
  expect_problem(full, 503, "queue-full");
  EXPECT_EQ(full->get_header_value("Retry-After"), "5");
}

TEST(HttpApi, ListsWithFiltersAndPages) {
  Service svc({}, false);
  auto cli = svc.client();
  for (int i = 0; i < 5; ++i) post_json(cli, "/v1/jobs", "{\"n\":" + std::to_string(i) + "}");
  cli.Post("/v1/jobs/2/cancel");
  std::vector<int> ids;
  std::string token;
  int pages = 0;
  do {
    std::string path = "/v1/jobs?page_size=2";
    if (!token.empty()) path += "&page_token=" + token;
    auto res = cli.Get(path.c_str());
    ASSERT_EQ(res->status, 200);
    json page = json::parse(res->body);
    for (auto& j : page["jobs"]) ids.push_back(j["id"]);
    token = page["next_page_token"].is_null() ? "" : page["next_page_token"].get<std::string>();
    ++pages;
  } while (!token.empty() && pages < 10);
  EXPECT_EQ(ids, (std::vector<int>{5, 4, 3, 2, 1}));
  EXPECT_EQ(pages, 3);
  json cancelled = json::parse(cli.Get("/v1/jobs?state=cancelled")->body);
  ASSERT_EQ(cancelled["jobs"].size(), 1u);
  EXPECT_EQ(cancelled["jobs"][0]["id"], 2);
  EXPECT_TRUE(cancelled["next_page_token"].is_null());
  expect_problem(cli.Get("/v1/jobs?state=done"), 400, "invalid-parameter");
  expect_problem(cli.Get("/v1/jobs?page_size=0"), 400);
  expect_problem(cli.Get("/v1/jobs?page_size=101"), 400);
  expect_problem(cli.Get("/v1/jobs?page_token=abc"), 400);
}

TEST(HttpApi, HealthMetricsAndLogLines) {
  Service svc({}, false);
  auto cli = svc.client();
  post_json(cli, "/v1/jobs", "{}");
  auto health = cli.Get("/healthz");
  ASSERT_EQ(health->status, 200);
  EXPECT_EQ(json::parse(health->body)["status"], "ok");
  // Requests are counted when they are logged, just after their response is written.
  const std::string posted =
      "fosls_http_requests_total{method=\"POST\",route=\"/v1/jobs\",status=\"202\"} 1";
  std::string metrics;
  for (int i = 0; i < 1000; ++i) {
    auto res = cli.Get("/metrics");
    ASSERT_EQ(res->status, 200);
    metrics = res->body;
    if (metrics.find(posted) != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_NE(metrics.find(posted), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("fosls_jobs{state=\"queued\"} 1"), std::string::npos);
  EXPECT_NE(metrics.find("fosls_queue_depth 1"), std::string::npos);
  EXPECT_NE(metrics.find("fosls_http_request_seconds_count"), std::string::npos);

  // One JSON line per request with method, path, status and duration. The logger runs
  // after the response is written, so wait (bounded) for the lines of the two requests.
  std::map<std::string, int> seen;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (seen["POST /v1/jobs 202"] == 0 || seen["GET /healthz 200"] == 0 ||
         seen["GET /metrics 200"] == 0) {
    ASSERT_LT(std::chrono::steady_clock::now(), give_up) << svc.log();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    seen.clear();
    std::istringstream lines(svc.log());
    std::string line;
    while (std::getline(lines, line)) {
      json event = json::parse(line, nullptr, false);
      if (event.is_discarded()) continue;  // a line being written right now
      if (event["event"] != "http_request") continue;
      EXPECT_TRUE(event["duration_ms"].is_number()) << line;
      ++seen[event["method"].get<std::string>() + " " + event["path"].get<std::string>() + " " +
             std::to_string(event["status"].get<int>())];
    }
  }
  EXPECT_EQ(seen["POST /v1/jobs 202"], 1);
  EXPECT_EQ(seen["GET /healthz 200"], 1);
  EXPECT_GE(seen["GET /metrics 200"], 1);
}

TEST(HttpApi, StaticFilesStayInsideTheWebRoot) {
  Service svc({}, false);
  auto cli = svc.client();
  auto index = cli.Get("/");
  ASSERT_EQ(index->status, 200);
  EXPECT_EQ(index->body, "<html>fosls</html>");
  EXPECT_EQ(index->get_header_value("Content-Type"), "text/html; charset=utf-8");
  auto js = cli.Get("/app.js");
  ASSERT_EQ(js->status, 200);
  EXPECT_EQ(js->get_header_value("Content-Type"), "text/javascript; charset=utf-8");
  expect_problem(cli.Get("/missing.css"), 404);
  for (const char* attack : {"/../secret.txt", "/%2e%2e/secret.txt", "/..%2fsecret.txt",
                             "/web/../../secret.txt", "/.hidden"}) {
    auto res = raw_http(svc.port(), std::string("GET ") + attack +
                                        " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
    EXPECT_NE(res.status, 200) << attack;
    EXPECT_EQ(res.text.find("outside the web root"), std::string::npos) << attack;
  }
}

TEST(HttpApi, RouteTemplatesKeepMetricLabelsBounded) {
  EXPECT_EQ(HttpApi::route_template("/v1/jobs"), "/v1/jobs");
  EXPECT_EQ(HttpApi::route_template("/v1/jobs/17"), "/v1/jobs/{id}");
  EXPECT_EQ(HttpApi::route_template("/v1/jobs/17/result"), "/v1/jobs/{id}/result");
  EXPECT_EQ(HttpApi::route_template("/v1/jobs/17/solution.vtu"), "/v1/jobs/{id}/solution.vtu");
  EXPECT_EQ(HttpApi::route_template("/v1/jobs/17/x"), "unknown");
  EXPECT_EQ(HttpApi::route_template("/index.html"), "static");
  EXPECT_EQ(HttpApi::route_template("/v1/jobs/17/cancel/x"), "unknown");
}

TEST(HttpApi, OneRouteTableForServerAllowHeadersAndOpenApi) {
  // The OpenAPI document lists exactly the routes of the table, method by method.
  std::set<std::pair<std::string, std::string>> table, documented;
  for (const ApiRoute& r : api_routes()) table.emplace(r.method, r.path);
  const nlohmann::json document = openapi_document();
  for (const auto& [path, operations] : document["paths"].items())
    for (const auto& [method, operation] : operations.items()) {
      std::string upper = method;
      for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      documented.emplace(upper, path);
    }
  EXPECT_EQ(table, documented);
  EXPECT_EQ(allowed_methods("/v1/jobs/3"), "GET, DELETE");
  EXPECT_EQ(allowed_methods("/v1/jobs"), "GET, POST");
  EXPECT_EQ(allowed_methods("/v1/jobs/3/cancel"), "POST");
  EXPECT_EQ(allowed_methods("/v1/jobs//cancel"), "");
  EXPECT_EQ(allowed_methods("/nowhere"), "");
  EXPECT_EQ(id_segment("/v1/jobs/{id}/result", "/v1/jobs/42/result"), "42");
  EXPECT_EQ(route_pattern("/v1/jobs/{id}/solution.vtu"), "/v1/jobs/([^/]+)/solution\\.vtu");
}

TEST(HttpApi, BodylessRequestsOnOddPathsAndGetOnAPostRoute) {
  Service svc({}, false);
  auto cli = svc.client();
  const auto id = json::parse(post_json(cli, "/v1/jobs", R"({"n":1})")->body)["id"].get<int>();
  const std::string job = "/v1/jobs/" + std::to_string(id);
  // No Content-Length at all (curl -X POST/DELETE): pre_route dispatches these without
  // reading a body, so a bad id, an extra segment or a trailing slash must be refused there.
  auto bodyless = [&](const std::string& method, const std::string& path) {
    return raw_http(svc.port(),
                    method + " " + path + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  };
  for (const std::string& path :
       {std::string("/v1/jobs/abc/cancel"), std::string("/v1/jobs/0/cancel")}) {
    auto r = bodyless("POST", path);
    EXPECT_EQ(r.status, 404) << r.text;
    EXPECT_NE(raw_body(r).find("job ids are positive integers"), std::string::npos) << r.text;
  }
  EXPECT_EQ(bodyless("DELETE", "/v1/jobs/abc").status, 404);
  for (const std::string& path : {job + "/cancel/extra", job + "/cancel/", job + "/"}) {
    EXPECT_EQ(bodyless("POST", path).status, 404) << path;
    EXPECT_EQ(bodyless("DELETE", path).status, 404) << path;
  }
  auto post_job = bodyless("POST", job);
  EXPECT_EQ(post_job.status, 405) << post_job.text;
  EXPECT_NE(post_job.text.find("Allow: GET, DELETE"), std::string::npos) << post_job.text;
  auto put_cancel = bodyless("PUT", job + "/cancel");
  EXPECT_EQ(put_cancel.status, 405) << put_cancel.text;
  EXPECT_NE(put_cancel.text.find("Allow: POST"), std::string::npos) << put_cancel.text;
  // None of them touched the job.
  EXPECT_EQ(json::parse(cli.Get(job.c_str())->body)["state"], "queued");
  // GET on the cancel route is a method that route lacks, not a missing resource.
  auto get_cancel = cli.Get((job + "/cancel").c_str());
  expect_problem(get_cancel, 405);
  EXPECT_EQ(get_cancel->get_header_value("Allow"), "POST");
  // Metric labels: the route's template, or "unknown" under /v1/.
  const std::string metrics = cli.Get("/metrics")->body;
  for (const char* line :
       {R"(fosls_http_requests_total{method="POST",route="/v1/jobs/{id}/cancel",status="404"} 2)",
        R"(fosls_http_requests_total{method="GET",route="/v1/jobs/{id}/cancel",status="405"} 1)",
        R"(fosls_http_requests_total{method="POST",route="unknown",status="404"} 3)"})
    EXPECT_NE(metrics.find(line), std::string::npos) << line << "\n" << metrics;
}

TEST(HttpApi, AFullDiskIs507NamingTheDiskAndHealthSaysSo) {
  TempDir dir;
  std::ofstream log_file(dir.file("service.log"));
  EventLog log(log_file);
  Metrics metrics;
  SqliteJobStore reads(dir.file("jobs.db"));
  testing::DiskFullStore store(reads);
  WorkerPoolOptions no_workers;
  no_workers.workers = 0;
  WorkerPool pool(store, fake_job_runner, log, metrics, no_workers);
  HttpApi api(store, pool, fake_validator, metrics, log, {});
  BoundedHttpServer server;
  api.install(server);
  const int port = server.bind_to_any_port("127.0.0.1");
  std::thread thread([&] { server.listen_after_bind(); });
  while (!server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  httplib::Client cli("127.0.0.1", port);

  auto posted = post_json(cli, "/v1/jobs", R"({"n":1})");
  expect_problem(posted, 507, "store-full");
  EXPECT_NE(json::parse(posted->body)["detail"].get<std::string>().find("disk is full"),
            std::string::npos)
      << posted->body;
  EXPECT_EQ(posted->get_header_value("Retry-After"), "5");
  auto health = cli.Get("/healthz");
  expect_problem(health, 503, "store-full");
  EXPECT_NE(health->body.find("database or disk is full"), std::string::npos) << health->body;
  // Reads still work.
  auto list = cli.Get("/v1/jobs");
  ASSERT_TRUE(list);
  EXPECT_EQ(list->status, 200);
  server.stop();
  thread.join();
}

}  // namespace
}  // namespace fosls::service
