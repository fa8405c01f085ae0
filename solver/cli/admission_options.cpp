#include "cli/admission_options.hpp"

#include "case/admission/memory_size.hpp"

namespace fosls {

void add_max_memory_option(CLI::App& command, std::string& text) {
  command
      .add_option("--max-memory", text,
                  "Memory a solve may use, e.g. 6G (default: this machine's memory); a case "
                  "estimated above it is refused, as the service refuses one above "
                  "--max-job-memory")
      ->check([](const std::string& value) {
        return parse_byte_size(value) ? std::string()
                                      : "expected a size such as 512M or 6G, got '" + value + "'";
      });
}

CaseReadOptions command_line_read_options(const std::string& max_memory) {
  CaseReadOptions options;
  options.allow_local_files = true;  // a local file given by the user who runs the program
  if (const auto bytes = parse_byte_size(max_memory)) {
    options.limits.max_memory_bytes = static_cast<double>(*bytes);
    options.limits.memory_budget_name = "a solve may use (--max-memory)";
  } else {
    options.limits.max_memory_bytes = static_cast<double>(physical_memory());
    options.limits.memory_budget_name = "this machine has (--max-memory gives another budget)";
  }
  return options;
}

}  // namespace fosls
