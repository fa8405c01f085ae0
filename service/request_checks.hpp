#pragma once
// Small pure checks on HTTP requests, kept apart from the handlers so they are unit-tested.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace fosls::service {

/// True for "application/json", with any parameters ("; charset=utf-8") and in any case.
bool is_json_media_type(std::string_view content_type);

/// Deepest nesting of arrays/objects in JSON text, ignoring brackets inside strings. Stops
/// counting once `limit` is exceeded, so huge bodies are not scanned twice for nothing.
int json_nesting_depth(std::string_view text, int limit);

/// A positive job id written in decimal, or nothing (overflow, sign, other characters).
std::optional<std::int64_t> parse_job_id(std::string_view text);

/// Whether an Idempotency-Key is acceptable: 1 to 255 visible ASCII characters.
bool is_valid_idempotency_key(std::string_view key);

/// Whether a Transfer-Encoding header asks for a chunked (unbounded) body.
bool is_chunked(std::string_view transfer_encoding);

/// SHA-256 of `data` as 64 lowercase hex digits.
std::string sha256_hex(std::string_view data);

}  // namespace fosls::service
