#pragma once
// Whether reading a case reported a problem at a JSON pointer, for tests of the case reader.
#include <algorithm>
#include <string>

#include "case/format/case_reader.hpp"

namespace fosls::testing {

/// Some error of `r` is at `pointer` and its detail contains `word` ("" matches any detail).
inline bool has_error(const CaseReadResult& r, const std::string& pointer,
                      const std::string& word) {
  return std::any_of(r.errors.begin(), r.errors.end(), [&](const CaseError& e) {
    return e.pointer == pointer && e.detail.find(word) != std::string::npos;
  });
}

}  // namespace fosls::testing
