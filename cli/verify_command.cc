#include <cstdio>

#include "cli/commands.h"

namespace arbc::cli {

// Placeholder until the stage behind `arbc verify` lands.
int verify_command(std::span<char*> args) {
  std::fputs("arbc verify: not implemented yet\n", stderr);
  return kExitBadInput;
}

}  // namespace arbc::cli
