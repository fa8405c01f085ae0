#include "cli/schema_command.hpp"

#include <iostream>
#include <memory>
#include <string>

#include "case/case_schema.hpp"
#include "cli/exit_codes.hpp"

namespace fosls {

void add_schema_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("schema", "Print the JSON Schema of a document (case)");
  auto which = std::make_shared<std::string>("case");
  cmd->add_option("DOCUMENT", *which, "Which schema: case")->check(CLI::IsMember({"case"}));
  cmd->callback([which, &exit_code] {
    std::cout << case_json_schema().dump(2) << '\n';
    exit_code = std::cout.good() ? kExitOk : kExitInternal;
  });
}

}  // namespace fosls
