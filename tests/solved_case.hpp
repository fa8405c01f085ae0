#pragma once
// A case JSON read and run as fosls-contact solve would, for tests that check its result.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"

namespace fosls::testing {

/// The result of running `j`; a case that does not read is a test failure naming its first
/// problem (and returns null).
inline nlohmann::json solved_case(const nlohmann::json& j) {
  const CaseReadResult read = read_case(j);
  EXPECT_TRUE(read.spec) << (read.errors.empty()
                                 ? ""
                                 : read.errors[0].pointer + ": " + read.errors[0].detail);
  return read.spec ? run_case(*read.spec).result : nlohmann::json();
}

}  // namespace fosls::testing
