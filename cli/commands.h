// The subcommands of `arbc` (docs/cli.md). Each takes the arguments after its name
// (args[0] is the command name) and returns the process exit code:
// 0 fine; 1 verification refuted or unknown; 2 bad input; 3 run-time failure.
#pragma once

#include <span>

namespace arbc::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRefuted = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitRuntimeFailure = 3;

int check_command(std::span<char*> args);
int verify_command(std::span<char*> args);
int build_command(std::span<char*> args);
int run_command(std::span<char*> args);
int docs_command(std::span<char*> args);
int import_command(std::span<char*> args);
int lsp_command(std::span<char*> args);
int test_command(std::span<char*> args);

}  // namespace arbc::cli
