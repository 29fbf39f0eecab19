#include <cstdio>

#include "cli/commands.h"

namespace arbc::cli {

// Placeholder until the stage behind `arbc build` lands.
int build_command(std::span<char*> args) {
  std::fputs("arbc build: not implemented yet\n", stderr);
  return kExitBadInput;
}

}  // namespace arbc::cli
