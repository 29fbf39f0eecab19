#include <cstdio>

#include "cli/commands.h"

namespace arbc::cli {

// Placeholder until the stage behind `arbc docs` lands.
int docs_command(std::span<char*> args) {
  std::fputs("arbc docs: not implemented yet\n", stderr);
  return kExitBadInput;
}

}  // namespace arbc::cli
