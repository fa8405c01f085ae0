#pragma once
// 3D cases for tests: the shipped hertz_3d at a given refinement, a case read and run, and the
// problems of a bad case, found when it is read or when it runs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "case/admission/case_admission.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"
#include "case/run/volume_mesh_checks.hpp"
#include "shipped_example.hpp"

namespace fosls::testing {

inline nlohmann::json hertz_3d(int refinements) {
  nlohmann::json j = load_shipped_example("3d/hertz_3d");
  j["mesh"]["refinements"] = refinements;
  return j;
}

/// The result of a case that must read cleanly (a read error is a test failure).
inline nlohmann::json run_3d(const nlohmann::json& j) {
  const auto read = read_case(j);
  EXPECT_TRUE(read.errors.empty()) << (read.errors.empty() ? "" : read.errors[0].detail);
  return run_case(*read.spec).result;
}

/// The first problem the run of a cleanly read case throws (a CaseException: what only the
/// mesh shows); empty pointer and detail when it runs.
inline CaseError run_3d_problem(const nlohmann::json& j) {
  try {
    run_3d(j);
  } catch (const CaseException& e) {
    return e.errors().front();
  }
  return {};
}

/// The pointers of the problems admission reports for `j` (what the case alone shows).
inline std::vector<std::string> case3d_problems(const nlohmann::json& j) {
  std::vector<std::string> pointers;
  for (const auto& e : admit_case(j).errors) pointers.push_back(e.pointer);
  return pointers;
}

/// A result's warnings but contact_zone_underresolved, which a coarse 3D mesh raises by design
/// (informational: its review is false), as "code: message".
inline std::vector<std::string> warnings_but_resolution(const nlohmann::json& r) {
  std::vector<std::string> others;
  for (const auto& w : r["warning_details"])
    if (w["code"] != "contact_zone_underresolved" || w["review"].get<bool>())
      others.push_back(w["code"].get<std::string>() + ": " + w["message"].get<std::string>());
  return others;
}

}  // namespace fosls::testing
