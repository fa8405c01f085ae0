#pragma once
// Duplicate keys in JSON text. nlohmann's parser keeps the last of two equal keys silently;
// the service refuses them, as it refuses unknown keys, so that what a client meant is never
// guessed.

#include <optional>
#include <string>
#include <string_view>

namespace fosls::service {

/// The JSON pointer (RFC 6901) of the first key that repeats a key of the same object, or
/// nothing (also for text that does not parse: the parser reports that).
std::optional<std::string> first_duplicate_key(std::string_view json_text);

}  // namespace fosls::service
