// What a command prints and returns when its command line does not parse.
#pragma once

#include <CLI/CLI.hpp>

namespace arbc::cli {

// CLI11's message and kExitBadInput (kExitOk for --help); a single misspelt option
// (`--frmat`) is named with the one meant instead: "arbc check: there is no option --frmat:
// did you mean '--format'?".
int exit_for_parse_error(CLI::App& app, const CLI::ParseError& e);

}  // namespace arbc::cli
