#include <cstdio>

#include "cli/commands.h"

namespace arbc::cli {

// Placeholder until the stage behind `arbc run` lands.
int run_command(std::span<char*> args) {
  std::fputs("arbc run: not implemented yet\n", stderr);
  return kExitBadInput;
}

}  // namespace arbc::cli
