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

}  // namespace fosls::service
