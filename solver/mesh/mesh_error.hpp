#pragma once
// A problem with a mesh source (geometry, msh text, .geo file, mesh size), located by a path
// relative to the mesh section of whatever describes it ("/geometry/curves/2", "/size", "/msh").
// The mesh layer knows nothing of the case JSON: the case layer maps these paths to JSON
// pointers (by prefixing "/mesh").

#include <stdexcept>
#include <string>
#include <vector>

namespace fosls {

struct MeshProblem {
  std::string field;   ///< path relative to the mesh section, "" for the mesh as a whole
  std::string detail;  ///< what is wrong and what to do about it
};

class MeshError : public std::runtime_error {
 public:
  explicit MeshError(std::vector<MeshProblem> problems);
  MeshError(std::string field, std::string detail);
  const std::vector<MeshProblem>& problems() const { return problems_; }

 private:
  std::vector<MeshProblem> problems_;
};

}  // namespace fosls
