#pragma once
// Base64 (RFC 4648, with padding), for the binary arrays of the VTU file.

#include <cstddef>
#include <string>

namespace fosls {

/// Appends the base64 encoding of `size` bytes at `data` to `out`.
void append_base64(std::string& out, const void* data, std::size_t size);

}  // namespace fosls
