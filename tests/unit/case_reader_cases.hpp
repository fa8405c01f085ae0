#pragma once
// The small valid case the case-reader tests break one field at a time, and the errors of a
// read as text for a failure's message (case_reader_test.cpp, case_reader_errors_test.cpp).
#include <string>
#include <vector>

#include "case/format/case_reader.hpp"

namespace fosls::testing {

inline nlohmann::json valid_case() {
  return nlohmann::json::parse(R"({
    "name": "t",
    "mesh": {"builtin": "square", "size": 0.5, "refinements": 1},
    "material": {"mu": 2, "lambda": 3},
    "boundary": {
      "top": {"type": "dirichlet", "displacement": [0, "-0.01*x"]},
      "bottom": {"type": "contact", "obstacle": {"type": "plane", "point": [0, -0.1],
                                                 "normal": [0, 2]}}
    }
  })");
}

inline std::string dump_errors(const std::vector<CaseError>& errors) {
  std::string s;
  for (const auto& e : errors) s += "  " + e.pointer + ": " + e.detail + "\n";
  return s;
}

}  // namespace fosls::testing
