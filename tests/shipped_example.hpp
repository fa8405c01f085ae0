#pragma once
// A shipped example case (solver/examples/NAME.json) as JSON, for tests that start from one.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace fosls::testing {

/// The example's JSON; a file that does not parse is a test failure (and returns a discarded
/// value).
inline nlohmann::json load_shipped_example(const std::string& name) {
  std::ifstream in(std::string(FOSLS_SOURCE_DIR) + "/solver/examples/" + name + ".json");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  if (j.is_discarded()) ADD_FAILURE() << "solver/examples/" << name << ".json does not parse";
  return j;
}

}  // namespace fosls::testing
