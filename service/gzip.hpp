#pragma once
// gzip (RFC 1952) compression of stored artefacts: a VTU file is XML text that shrinks several
// times, and gzip is what an HTTP client can also take as Content-Encoding.

#include <string>
#include <string_view>

namespace fosls::service {

/// Compresses `data` into the gzip format.
std::string gzip_compress(std::string_view data);

/// Inverse of gzip_compress; throws StoreError when `data` is not a complete gzip stream.
std::string gzip_decompress(std::string_view data);

}  // namespace fosls::service
