// set_stored_vtu_body and set_stored_result_body: a stored VTU and result sent part by part. A
// browser's Accept-Encoding (gzip, deflate, br) gets the stored gzip bytes of the VTU, never
// cpp-httplib's brotli at quality 11 (51 s for an 18.7 MB VTU); a client without gzip gets the
// text decompressed on the way, byte ranges included. Either way the client reads exactly the
// VTU and result, and the store is asked for parts of at most kStoredPart bytes, never for the
// whole VTU or result.
#include "stored_body.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "forwarding_store.hpp"
#include "gzip.hpp"
#include "store_test_support.hpp"

namespace fosls::service {
namespace {

/// Counts what the responses read: whole VTUs, parts and the largest part.
class CountingStore : public testing::ForwardingStore {
 public:
  using ForwardingStore::ForwardingStore;
  std::optional<std::string> vtu(std::int64_t id) override {
    ++whole;
    return ForwardingStore::vtu(id);
  }
  std::optional<std::string> result_json(std::int64_t id) override {
    ++whole;
    return ForwardingStore::result_json(id);
  }
  std::optional<std::string> result_json_bytes(std::int64_t id, std::int64_t offset,
                                               std::int64_t length) override {
    ++parts;
    largest = std::max<std::int64_t>(largest, length);
    return ForwardingStore::result_json_bytes(id, offset, length);
  }
  std::optional<std::string> stored_vtu_bytes(std::int64_t id, std::int64_t offset,
                                              std::int64_t length) override {
    if (++parts == delete_at_part) remove(id);
    largest = std::max<std::int64_t>(largest, length);
    return ForwardingStore::stored_vtu_bytes(id, offset, length);
  }
  std::atomic<int> whole{0}, parts{0};
  int delete_at_part = 0;  ///< the job is deleted before this part is read (0: never)
  std::atomic<std::int64_t> largest{0};
};

std::string vtu_like_text() {
  std::string text = "<VTKFile type=\"UnstructuredGrid\">\n";
  for (int i = 0; i < 200000; ++i) text += std::to_string(i * 0.001) + " 0.25 0\n";
  return text + "</VTKFile>\n";
}

/// A SQLite store holding one finished job (id 1) with `vtu` and `result`, served at GET /vtu
/// and GET /result.
class StoredVtuServer {
 public:
  explicit StoredVtuServer(const std::string& vtu,
                           const std::string& result = R"({"converged": true})")
      : store_(dir_.file("jobs.db")), counting_(store_) {
    store_.submit(testing::make_job("{}"), testing::kUnlimited);
    const auto claimed = store_.claim_next(testing::claim_as());
    store_.complete_succeeded(claimed->lease, result, vtu);
    server_.Get("/result", [this](const httplib::Request&, httplib::Response& res) {
      if (const auto bytes = counting_.result_json_size(1))
        set_stored_result_body(res, counting_, 1, *bytes);
      else
        res.status = 404;
    });
    server_.Get("/vtu", [this](const httplib::Request& req, httplib::Response& res) {
      if (const auto stored = counting_.stored_vtu(1))
        set_stored_vtu_body(req, res, counting_, 1, *stored, "application/xml");
      else
        res.status = 404;
    });
    port_ = server_.bind_to_any_port("127.0.0.1");
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ~StoredVtuServer() {
    server_.stop();
    thread_.join();
  }
  /// GET `path` with these headers, the body left encoded as sent.
  httplib::Result get(const httplib::Headers& headers, const std::string& path = "/vtu") {
    httplib::Client cli("127.0.0.1", port_);
    cli.set_decompress(false);
    return cli.Get(path, headers);
  }
  CountingStore& counted() { return counting_; }
  std::string db() const { return dir_.file("jobs.db"); }

 private:
  testing::TempDir dir_;
  SqliteJobStore store_;
  CountingStore counting_;
  httplib::Server server_;
  int port_ = 0;
  std::thread thread_;
};

TEST(StoredVtuBody, ABrowserGetsTheStoredGzipNotBrotli) {
  const std::string text = vtu_like_text();
  StoredVtuServer server(text);
  auto res = server.get({{"Accept-Encoding", "gzip, deflate, br"}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(res->get_header_value("Content-Encoding"), "gzip");
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/xml");
  EXPECT_EQ(res->get_header_value("Vary"), "Accept-Encoding");
  EXPECT_LT(res->body.size(), text.size() / 2);
  EXPECT_EQ(gzip_decompress(res->body), text);
  EXPECT_EQ(server.counted().whole, 0);
  EXPECT_GT(server.counted().parts, 1) << "sent in one part: the test's VTU is too small";
  EXPECT_LE(server.counted().largest, kStoredPart);
}

TEST(StoredVtuBody, WithoutGzipTheTextIsDecompressedOnTheWay) {
  const std::string text = vtu_like_text();
  ASSERT_GT(text.size(), 8u * kStoredPart);
  StoredVtuServer server(text);
  for (const char* accept : {"br", "identity", ""}) {
    auto res = server.get({{"Accept-Encoding", accept}});
    ASSERT_TRUE(res) << accept;
    EXPECT_FALSE(res->has_header("Content-Encoding")) << accept;
    EXPECT_EQ(res->get_header_value("Content-Length"), std::to_string(text.size())) << accept;
    EXPECT_TRUE(res->body == text) << accept << ": " << res->body.size() << " bytes";
  }
  EXPECT_EQ(server.counted().whole, 0);
  EXPECT_LE(server.counted().largest, kStoredPart);
}

TEST(StoredVtuBody, ByteRangesOfTheTextAndOfTheGzip) {
  const std::string text = vtu_like_text();
  StoredVtuServer server(text);
  const std::size_t far = text.size() - 1000;  // beyond the first parts: decompressed up to it
  for (const auto& [from, to] : {std::pair<std::size_t, std::size_t>{far, far + 99},
                                 {10, 4009},
                                 {kStoredPart - 5, kStoredPart + 5}}) {
    auto res = server.get({{"Range", "bytes=" + std::to_string(from) + "-" + std::to_string(to)}});
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 206);
    EXPECT_EQ(res->body, text.substr(from, to - from + 1)) << from << "-" << to;
  }
  auto whole = server.get({{"Accept-Encoding", "gzip"}});
  auto head = server.get({{"Accept-Encoding", "gzip"}, {"Range", "bytes=0-99"}});
  ASSERT_TRUE(whole && head);
  EXPECT_EQ(head->status, 206);
  EXPECT_EQ(head->body, whole->body.substr(0, 100));
}

TEST(StoredVtuBody, TheResultIsSentAsStoredInParts) {
  // Over 256 KiB of JSON with text that is not ASCII: parts are bytes, not characters.
  nlohmann::json result = {{"converged", true}, {"name", "Kontakt – Prüfung ✓"}, {"steps", {}}};
  for (int k = 0; result.dump().size() < 3 * kStoredPart; ++k)
    result["steps"].push_back({{"step", k}, {"force", k * 0.125}, {"note", "Über σ = 1"}});
  const std::string text = result.dump();
  StoredVtuServer server("<VTKFile/>", text);
  for (const char* accept : {"gzip, deflate, br", ""}) {
    auto res = server.get({{"Accept-Encoding", accept}}, "/result");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200);
    EXPECT_FALSE(res->has_header("Content-Encoding")) << accept;  // never brotli at quality 11
    EXPECT_EQ(res->get_header_value("Content-Type"), "application/json");
    EXPECT_EQ(res->get_header_value("Content-Length"), std::to_string(text.size()));
    EXPECT_TRUE(res->body == text) << accept;
  }
  auto range = server.get({{"Range", "bytes=300000-300099"}}, "/result");
  ASSERT_TRUE(range);
  EXPECT_EQ(range->body, text.substr(300000, 100));
  EXPECT_EQ(server.counted().whole, 0);
  EXPECT_GT(server.counted().parts, 2);
  EXPECT_LE(server.counted().largest, kStoredPart);
}

TEST(StoredVtuBody, ARowFromBeforeCompressionIsSentAsItIs) {
  StoredVtuServer server("unused");
  const std::string text = vtu_like_text();
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(server.db().c_str(), &db), SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db,
                               "UPDATE job_results SET vtu = ?1, vtu_encoding = 'identity' "
                               "WHERE job_id = 1",
                               -1, &stmt, nullptr),
            SQLITE_OK);
  sqlite3_bind_text(stmt, 1, text.data(), static_cast<int>(text.size()), SQLITE_TRANSIENT);
  EXPECT_EQ(sqlite3_step(stmt), SQLITE_DONE);
  sqlite3_finalize(stmt);
  sqlite3_close(db);
  for (const char* accept : {"gzip", ""}) {
    auto res = server.get({{"Accept-Encoding", accept}});
    ASSERT_TRUE(res);
    EXPECT_FALSE(res->has_header("Content-Encoding")) << accept;
    EXPECT_TRUE(res->body == text) << accept;
  }
}

TEST(StoredVtuBody, AResultDeletedWhileSentEndsTheConnection) {
  const std::string text = vtu_like_text();
  for (const char* accept : {"gzip", ""}) {
    StoredVtuServer server(text);
    server.counted().delete_at_part = 2;  // the gzip is sent in 2 or more parts
    auto res = server.get({{"Accept-Encoding", accept}});
    // The client sees the body end before its Content-Length: an error, not a short VTU.
    EXPECT_FALSE(res && res->status == 200 && res->body.size() == text.size()) << accept;
    EXPECT_FALSE(server.counted().stored_vtu(1)) << "the job was not deleted";
    EXPECT_FALSE(server.counted().stored_vtu_bytes(1, 0, 10)) << "a part of a deleted job";
    auto again = server.get({});  // answered: nothing there now
    ASSERT_TRUE(again) << accept;
    EXPECT_EQ(again->status, 404);
  }
}

}  // namespace
}  // namespace fosls::service
