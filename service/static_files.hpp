#pragma once
// Files of the web page under --web-root, resolved so that no request can leave that folder.

#include <filesystem>
#include <optional>
#include <string_view>

namespace fosls::service {

/// The regular file a URL path names under `root` ("/" and folders mean their index.html),
/// or nothing when it does not exist or would leave `root`: ".." and hidden segments are
/// refused, and symbolic links must resolve inside `root`. `url_path` is already
/// percent-decoded.
std::optional<std::filesystem::path> resolve_static_file(const std::filesystem::path& root,
                                                         std::string_view url_path);

/// Content-Type for a file name's extension (application/octet-stream when unknown).
std::string_view content_type_for(const std::filesystem::path& file);

}  // namespace fosls::service
