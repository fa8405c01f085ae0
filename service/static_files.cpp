#include "static_files.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <system_error>

namespace fosls::service {

namespace {
bool is_within(const std::filesystem::path& inner, const std::filesystem::path& outer) {
  auto [o, i] = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
  return o == outer.end();
}
}  // namespace

std::optional<std::filesystem::path> resolve_static_file(const std::filesystem::path& root,
                                                         std::string_view url_path) {
  namespace fs = std::filesystem;
  if (url_path.empty() || url_path.front() != '/') return std::nullopt;
  fs::path relative;
  std::size_t start = 1;
  while (start <= url_path.size()) {
    std::size_t end = url_path.find('/', start);
    if (end == std::string_view::npos) end = url_path.size();
    const std::string_view segment = url_path.substr(start, end - start);
    start = end + 1;
    if (segment.empty()) continue;
    // Dot segments would climb out; hidden files (.git, .env) are never part of the page.
    if (segment.front() == '.') return std::nullopt;
    if (segment.find_first_of(std::string_view("\\\0", 2)) != std::string_view::npos) {
      return std::nullopt;
    }
    relative /= fs::path(std::string(segment));
  }
  std::error_code ec;
  const fs::path canonical_root = fs::canonical(root, ec);
  if (ec) return std::nullopt;
  fs::path candidate = fs::canonical(canonical_root / relative, ec);
  if (ec || !is_within(candidate, canonical_root)) return std::nullopt;
  if (fs::is_directory(candidate, ec)) {
    candidate = fs::canonical(candidate / "index.html", ec);
    if (ec || !is_within(candidate, canonical_root)) return std::nullopt;
  }
  if (!fs::is_regular_file(candidate, ec)) return std::nullopt;
  return candidate;
}

std::string_view content_type_for(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".html" || ext == ".htm") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json") return "application/json";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".png") return "image/png";
  if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
  if (ext == ".ico") return "image/x-icon";
  if (ext == ".txt" || ext == ".md") return "text/plain; charset=utf-8";
  if (ext == ".wasm") return "application/wasm";
  if (ext == ".vtu" || ext == ".xml") return "application/xml";
  return "application/octet-stream";
}

}  // namespace fosls::service
