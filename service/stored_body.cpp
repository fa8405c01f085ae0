#include "stored_body.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "gzip.hpp"

namespace fosls::service {

namespace {

/// Reads up to `length` stored bytes from `offset`; nothing when they are gone.
using PartReader =
    std::function<std::optional<std::string>(std::int64_t offset, std::int64_t length)>;

/// The stored bytes as they are, read at the offsets the server asks for.
httplib::ContentProvider stored_bytes(PartReader read) {
  return [read = std::move(read)](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
    const auto part =
        read(static_cast<std::int64_t>(offset), std::min<std::int64_t>(length, kStoredPart));
    if (!part || part->empty()) return false;  // deleted meanwhile: the connection ends
    return sink.write(part->data(), part->size());
  };
}

/// The decompressed text, one window of kStoredPart bytes at a time. Sequential reads
/// continue the stream; an offset before the window (a second byte range) starts it again.
class InflatingReader {
 public:
  InflatingReader(JobStore& store, std::int64_t id) : store_(store), id_(id) { restart(); }

  bool provide(std::size_t offset, std::size_t length, httplib::DataSink& sink) {
    if (offset < window_at_) restart();
    while (offset >= window_at_ + window_.size()) {
      window_at_ += window_.size();
      window_.resize(static_cast<std::size_t>(kStoredPart));
      window_.resize(produce(window_.data(), window_.size()));
      if (window_.empty()) return false;  // shorter than its trailer said, or deleted
    }
    const std::size_t from = offset - window_at_;
    return sink.write(window_.data() + from, std::min(length, window_.size() - from));
  }

 private:
  void restart() {
    inflater_ = std::make_unique<GzipInflater>();
    read_ = 0;
    window_at_ = 0;
    window_.clear();
  }

  /// The next decompressed bytes into out[0, capacity); 0 at the end of the stream.
  std::size_t produce(char* out, std::size_t capacity) {
    while (!inflater_->finished()) {
      if (inflater_->needs_input()) {
        auto part = store_.stored_vtu_bytes(id_, read_, kStoredPart);
        if (!part || part->empty()) return 0;
        read_ += static_cast<std::int64_t>(part->size());
        inflater_->feed(std::move(*part));
      }
      if (const std::size_t n = inflater_->inflate_into(out, capacity); n > 0) return n;
    }
    return 0;
  }

  JobStore& store_;
  std::int64_t id_;
  std::unique_ptr<GzipInflater> inflater_;
  std::int64_t read_ = 0;      ///< stored bytes fed to the inflater
  std::size_t window_at_ = 0;  ///< offset of window_ in the decompressed text
  std::string window_;
};

}  // namespace

void set_stored_vtu_body(const httplib::Request& req, httplib::Response& res, JobStore& store,
                         std::int64_t id, const StoredVtu& stored,
                         const std::string& content_type) {
  res.set_header("Vary", "Accept-Encoding");
  const bool takes_gzip = req.get_header_value("Accept-Encoding").find("gzip") != std::string::npos;
  // Rows from before compression (SQLite's first schema) are sent as they are to anyone.
  if (!stored.gzip || takes_gzip) {
    if (stored.gzip) res.set_header("Content-Encoding", "gzip");
    res.set_content_provider(static_cast<std::size_t>(stored.bytes), content_type,
                             stored_bytes([&store, id](std::int64_t offset, std::int64_t length) {
                               return store.stored_vtu_bytes(id, offset, length);
                             }));
    return;
  }
  const auto trailer = store.stored_vtu_bytes(id, stored.bytes - 4, 4);
  if (!trailer) throw StoreError("the job's result was deleted while it was read");
  auto reader = std::make_shared<InflatingReader>(store, id);
  res.set_content_provider(
      gzip_recorded_size(*trailer), content_type,
      [reader](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
        return reader->provide(offset, length, sink);
      });
}

void set_stored_result_body(httplib::Response& res, JobStore& store, std::int64_t id,
                            std::int64_t bytes) {
  res.set_content_provider(static_cast<std::size_t>(bytes), "application/json",
                           stored_bytes([&store, id](std::int64_t offset, std::int64_t length) {
                             return store.result_json_bytes(id, offset, length);
                           }));
}

}  // namespace fosls::service
