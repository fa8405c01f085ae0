#pragma once
// Reading a case file for the command line: size limit, JSON parse errors with their
// position, and relative mesh.geo_file and mesh.msh_file paths taken relative to the case file.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace fosls {

/// A parsed case file, or the reason it could not be read or parsed.
struct CaseFile {
  nlohmann::json json;  ///< the parsed case (null when `problem` is set)
  std::string problem;  ///< empty on success, else a sentence for the user
};

/// Reads and parses `path` ("-" reads standard input). Files larger than `max_bytes` are
/// refused. A relative `mesh.geo_file` or `mesh.msh_file` is rewritten relative to the case
/// file's folder, so that a case runs the same from any working directory.
CaseFile load_case_file(const std::string& path, std::size_t max_bytes);

}  // namespace fosls
