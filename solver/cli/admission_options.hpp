#pragma once
// The admission rule the CLI's estimate, solve and bench share with the service
// (case/admission/case_admission.hpp): the same read options and the same memory budget, given by
// --max-memory (default: this machine's memory), so that estimate refuses exactly what solve
// refuses.

#include <CLI/CLI.hpp>
#include <string>

#include "case/format/case_reader.hpp"

namespace fosls {

/// --max-memory SIZE on `command`, written into `text` ("" keeps the default).
void add_max_memory_option(CLI::App& command, std::string& text);

/// The read options of a case given on the command line (local mesh files allowed) with the
/// memory budget of --max-memory `text` (the machine's memory when empty).
CaseReadOptions command_line_read_options(const std::string& max_memory);

}  // namespace fosls
