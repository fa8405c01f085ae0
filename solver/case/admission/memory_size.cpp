#include "case/admission/memory_size.hpp"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace fosls {

std::optional<std::size_t> parse_byte_size(std::string_view text) {
  std::string s(text);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  auto strip = [&s](std::string_view suffix) {
    if (s.size() > suffix.size() &&
        s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0) {
      s.resize(s.size() - suffix.size());
      return true;
    }
    return false;
  };
  if (!strip("ib")) strip("b");
  double scale = 1;
  if (!s.empty()) {
    switch (s.back()) {
      case 'k':
        scale = 1024.0;
        break;
      case 'm':
        scale = 1024.0 * 1024;
        break;
      case 'g':
        scale = 1024.0 * 1024 * 1024;
        break;
      case 't':
        scale = 1024.0 * 1024 * 1024 * 1024;
        break;
      default:
        break;
    }
    if (scale != 1) s.pop_back();
  }
  if (s.empty() || !(std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '.'))
    return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(value) || value <= 0) return std::nullopt;
  const double bytes = value * scale;
  if (bytes < 1 || bytes > 1e18) return std::nullopt;
  return static_cast<std::size_t>(bytes);
}

std::string format_bytes(double bytes) {
  char text[32];
  if (bytes >= double(std::size_t{1} << 30))
    std::snprintf(text, sizeof text, "%.3g GiB", bytes / double(std::size_t{1} << 30));
  else
    std::snprintf(text, sizeof text, "%.3g MiB", bytes / double(std::size_t{1} << 20));
  return text;
}

std::size_t physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::size_t{4} << 30;
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page);
}

}  // namespace fosls
