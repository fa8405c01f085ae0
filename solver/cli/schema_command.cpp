#include "cli/schema_command.hpp"

#include <iostream>
#include <memory>
#include <string>

#include "case/format/published_formats.hpp"
#include "cli/exit_codes.hpp"

namespace fosls {

void add_schema_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("schema", "Print the JSON Schema of the case or the result");
  auto which = std::make_shared<std::string>("case");
  cmd->add_option("DOCUMENT", *which,
                  "case (default) or result, of either dimension (case3d is the case's schema, "
                  "kept for scripts of the former 3D format; result3d a 3D case's result)")
      ->check(CLI::IsMember({"case", "case3d", "result", "result3d"}));
  cmd->callback([which, &exit_code] {
    const auto schema = *which == "result"     ? result_json_schema()
                        : *which == "result3d" ? result3d_json_schema()
                                               : case_json_schema();
    std::cout << schema.dump(2) << '\n';
    exit_code = std::cout.good() ? kExitOk : kExitInternal;
  });
}

}  // namespace fosls
