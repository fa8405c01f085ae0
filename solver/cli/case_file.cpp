#include "cli/case_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace fosls {

namespace {

/// Reads at most max_bytes + 1 bytes, so that an oversized input is detected without reading
/// all of it (the file may be a pipe whose size is unknown).
bool read_bounded(std::istream& in, std::size_t max_bytes, std::string& text) {
  text.clear();
  char buffer[1 << 16];
  while (in && text.size() <= max_bytes) {
    in.read(buffer, sizeof buffer);
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
  }
  return !in.bad();
}

std::string parse_problem(const std::string& text) {
  try {
    const auto parsed = nlohmann::json::parse(text);
    (void)parsed;
  } catch (const nlohmann::json::exception& e) {
    // Drop the library's "[json.exception.parse_error.101] " prefix.
    std::string message = e.what();
    if (!message.empty() && message[0] == '[') {
      const auto end = message.find("] ");
      if (end != std::string::npos) message.erase(0, end + 2);
    }
    return "invalid JSON: " + message;
  }
  return "invalid JSON";
}

/// Relative paths of local files in the mesh section, taken relative to the case's folder.
void resolve_mesh_paths(nlohmann::json& j, const std::filesystem::path& folder) {
  if (!j.is_object()) return;
  auto mesh = j.find("mesh");
  if (mesh == j.end() || !mesh->is_object()) return;
  for (const char* key : {"geo_file", "msh_file"}) {
    auto file = mesh->find(key);
    if (file == mesh->end() || !file->is_string()) continue;
    const std::filesystem::path path = file->get<std::string>();
    if (path.empty() || path.is_absolute()) continue;
    *file = (folder / path).lexically_normal().string();
  }
}

}  // namespace

CaseFile load_case_file(const std::string& path, std::size_t max_bytes) {
  CaseFile result;
  std::string text;
  std::filesystem::path folder;
  if (path == "-") {
    if (!read_bounded(std::cin, max_bytes, text)) {
      result.problem = "cannot read standard input";
      return result;
    }
  } else {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) {
      result.problem = "no such file";
      return result;
    }
    if (std::filesystem::is_directory(status)) {
      result.problem = "this is a folder, not a case file";
      return result;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      result.problem = std::string("cannot open the file: ") + std::strerror(errno);
      return result;
    }
    if (!read_bounded(in, max_bytes, text)) {
      result.problem = "cannot read the file";
      return result;
    }
    folder = std::filesystem::absolute(path, ec).parent_path();
  }
  if (text.size() > max_bytes) {
    result.problem = "the case is larger than the limit of " + std::to_string(max_bytes) + " bytes";
    return result;
  }
  result.json = nlohmann::json::parse(text, nullptr, false);
  if (result.json.is_discarded()) {
    result.json = nullptr;
    result.problem = parse_problem(text);
    return result;
  }
  if (!folder.empty()) resolve_mesh_paths(result.json, folder);
  return result;
}

}  // namespace fosls
