#include "cli/example_command.hpp"

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/exit_codes.hpp"
#include "cli/shipped_examples.hpp"

namespace fosls {

namespace {

int run_example(const std::string& requested) {
  std::vector<ShippedExample> examples(shipped_examples().begin(), shipped_examples().end());
  examples.insert(examples.end(), shipped_3d_examples().begin(), shipped_3d_examples().end());
  if (requested.empty()) {
    for (const auto& e : examples) std::cout << e.name << '\n';
    return kExitOk;
  }
  std::string name = requested;
  if (name.size() > 5 && name.ends_with(".json")) name.resize(name.size() - 5);
  for (const auto& e : examples)
    if (e.name == name) {
      std::cout << e.text;
      if (!e.text.ends_with('\n')) std::cout << '\n';
      return std::cout.good() ? kExitOk : kExitInternal;
    }
  std::cerr << "error: unknown example \"" << requested << "\"; the shipped examples are:";
  for (const auto& e : examples) std::cerr << ' ' << e.name;
  std::cerr << '\n';
  return kExitBadInput;
}

}  // namespace

void add_example_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "example", "Print a shipped example case (without NAME: list the shipped examples)");
  auto name = std::make_shared<std::string>();
  cmd->add_option("NAME", *name, "Name of the example, e.g. hertz");
  cmd->callback([name, &exit_code] { exit_code = run_example(*name); });
}

}  // namespace fosls
