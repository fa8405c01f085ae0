#include "gzip.hpp"

#include <zlib.h>

#include <limits>

#include "job_store.hpp"

namespace fosls::service {

namespace {
// windowBits 15 + 16: the gzip wrapper instead of the zlib one.
constexpr int kGzipWindowBits = 15 + 16;
// zlib counts in uInt; larger inputs are fed in pieces.
constexpr std::size_t kPiece = std::size_t{1} << 30;
}  // namespace

std::string gzip_compress(std::string_view data) {
  z_stream z{};
  // Level 1: a sixth of level 6's CPU for about 10 % more bytes (docs/service.md, "Storage");
  // the worker pays it on every job.
  if (deflateInit2(&z, 1, Z_DEFLATED, kGzipWindowBits, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
    throw StoreError("gzip: deflateInit2 failed");
  }
  std::string out;
  out.resize(deflateBound(&z, static_cast<uLong>(std::min(data.size(), kPiece))) + 64);
  std::size_t consumed = 0;
  int rc = Z_OK;
  do {
    const std::size_t piece = std::min(data.size() - consumed, kPiece);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + consumed));
    z.avail_in = static_cast<uInt>(piece);
    consumed += piece;
    const int flush = consumed == data.size() ? Z_FINISH : Z_NO_FLUSH;
    do {
      if (z.total_out == out.size()) out.resize(out.size() * 2);
      z.next_out = reinterpret_cast<Bytef*>(out.data() + z.total_out);
      z.avail_out = static_cast<uInt>(
          std::min<std::size_t>(out.size() - z.total_out, std::numeric_limits<uInt>::max()));
      rc = deflate(&z, flush);
    } while (z.avail_out == 0 || (flush == Z_FINISH && rc == Z_OK));
  } while (consumed < data.size());
  out.resize(z.total_out);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw StoreError("gzip: compression failed");
  return out;
}

std::string gzip_decompress(std::string_view data) {
  z_stream z{};
  if (inflateInit2(&z, kGzipWindowBits) != Z_OK) throw StoreError("gzip: inflateInit2 failed");
  std::string out;
  out.resize(std::max<std::size_t>(data.size() * 4, 1024));
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(std::min(data.size(), kPiece));
  std::size_t fed = z.avail_in;
  int rc = Z_OK;
  while (rc == Z_OK) {
    if (z.avail_in == 0 && fed < data.size()) {
      const std::size_t piece = std::min(data.size() - fed, kPiece);
      z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + fed));
      z.avail_in = static_cast<uInt>(piece);
      fed += piece;
    }
    if (z.total_out == out.size()) out.resize(out.size() * 2);
    z.next_out = reinterpret_cast<Bytef*>(out.data() + z.total_out);
    z.avail_out = static_cast<uInt>(
        std::min<std::size_t>(out.size() - z.total_out, std::numeric_limits<uInt>::max()));
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc == Z_BUF_ERROR && z.avail_in == 0 && fed == data.size()) break;  // truncated input
    if (rc == Z_BUF_ERROR) rc = Z_OK;  // no room: the loop grows the buffer
  }
  out.resize(z.total_out);
  inflateEnd(&z);
  if (rc != Z_STREAM_END) throw StoreError("stored artefact is not a complete gzip stream");
  return out;
}

std::uint32_t gzip_recorded_size(std::string_view trailer) {
  if (trailer.size() < 4) throw StoreError("a gzip stream ends with its 4-byte size");
  std::uint32_t size = 0;
  for (int k = 3; k >= 0; --k)
    size = (size << 8) | static_cast<unsigned char>(trailer[trailer.size() - 4 + k]);
  return size;
}

struct GzipInflater::State {
  z_stream z{};
};

GzipInflater::GzipInflater() : state_(std::make_unique<State>()) {
  if (inflateInit2(&state_->z, kGzipWindowBits) != Z_OK)
    throw StoreError("gzip: inflateInit2 failed");
}

GzipInflater::~GzipInflater() { inflateEnd(&state_->z); }

void GzipInflater::feed(std::string piece) {
  input_ = std::move(piece);
  state_->z.next_in = reinterpret_cast<Bytef*>(input_.data());
  state_->z.avail_in = static_cast<uInt>(input_.size());
}

bool GzipInflater::needs_input() const { return !finished_ && state_->z.avail_in == 0; }

std::size_t GzipInflater::inflate_into(char* out, std::size_t capacity) {
  if (finished_ || capacity == 0) return 0;
  z_stream& z = state_->z;
  z.next_out = reinterpret_cast<Bytef*>(out);
  z.avail_out = static_cast<uInt>(std::min<std::size_t>(capacity, kPiece));
  const uInt before = z.avail_out;
  const int rc = inflate(&z, Z_NO_FLUSH);
  if (rc == Z_STREAM_END)
    finished_ = true;
  else if (rc != Z_OK && rc != Z_BUF_ERROR)  // Z_BUF_ERROR: no input left, feed more
    throw StoreError("stored artefact is not a valid gzip stream");
  return before - z.avail_out;
}

}  // namespace fosls::service
