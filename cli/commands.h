// The subcommands of `arbc` (docs/cli.md). Each takes the arguments after its name
// (args[0] is the command name) and returns the process exit code:
// 0 fine; 1 verification refuted or unknown; 2 bad input; 3 run-time failure.
#pragma once

#include <span>
#include <string>

#include "compiler/codegen/target.h"

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
int status_command(std::span<char*> args);

// What `arbc build` is asked (its options, docs/cli.md#arbc-build).
struct BuildRequest {
  std::string spec;
  std::string out_dir = "out";
  std::string target_name{codegen::kDefaultTarget};
  std::string deploy;
  bool no_verify = false;
  bool strict = false;
  bool stats = false;
};

// The build itself, as `arbc build` runs it and `arbc run SPEC` calls it: compile, prove (unless
// no_verify), write OUT/<app>/, print the diagnostics and the summary. Returns the exit code;
// on success *app_dir is the directory written.
int build_spec(const BuildRequest& request, std::string* app_dir);

}  // namespace arbc::cli
