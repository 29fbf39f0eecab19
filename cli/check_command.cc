#include <cstdio>

#include "cli/commands.h"

namespace arbc::cli {

// Placeholder until the stage behind `arbc check` lands.
int check_command(std::span<char*> args) {
  std::fputs("arbc check: not implemented yet\n", stderr);
  return kExitBadInput;
}

}  // namespace arbc::cli
