#pragma once
// gzip (RFC 1952) compression of stored artefacts: a VTU file is XML text that shrinks several
// times, and gzip is what an HTTP client can also take as Content-Encoding.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace fosls::service {

/// Compresses `data` into the gzip format.
std::string gzip_compress(std::string_view data);

/// Inverse of gzip_compress; throws StoreError when `data` is not a complete gzip stream.
std::string gzip_decompress(std::string_view data);

/// The size of a gzip stream's content as its trailer records it (RFC 1952's ISIZE: modulo
/// 2^32), from the stream's last four bytes.
std::uint32_t gzip_recorded_size(std::string_view trailer);

/// Decompresses a gzip stream piece by piece, holding zlib's state (about 40 KiB) instead of
/// the whole output: for sending a stored VTU to a client that does not take gzip.
class GzipInflater {
 public:
  GzipInflater();
  ~GzipInflater();
  GzipInflater(const GzipInflater&) = delete;
  GzipInflater& operator=(const GzipInflater&) = delete;

  /// The next piece of the compressed stream, kept until it is used up (needs_input()).
  void feed(std::string piece);
  /// True when the piece fed last is used up and the stream has not ended.
  bool needs_input() const;
  /// True once the whole stream is decompressed.
  bool finished() const { return finished_; }
  /// Decompresses into out[0, capacity): the number of bytes written (0 when it needs input
  /// or has finished). Throws StoreError when the stream is not gzip or is corrupt.
  std::size_t inflate_into(char* out, std::size_t capacity);

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::string input_;
  bool finished_ = false;
};

}  // namespace fosls::service
