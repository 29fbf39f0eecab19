// arbc: compile, verify, run and document port-arbitrated robot applications.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <string_view>

#include "cli/commands.h"
#include "cli/heap_reserve.h"
#include "cli/left_at_exit.h"
#include "core/suggest.h"

namespace {

constexpr const char* kUsage =
    "usage: arbc <command> [options]\n"
    "\n"
    "commands:\n"
    "  check  SPEC...                parse and semantic checks\n"
    "  verify [SPEC | APP.json | APP.xml]...\n"
    "                                prove that at most one rule per arbitrated port is selected\n"
    "                                (by priority: a rule's delivery holds the rules below off)\n"
    "  build  SPEC [-o DIR]          verify, then write app.json and the Lua monitors\n"
    "  run    DIR|SPEC [options]     run the application on the embedded runtime\n"
    "  status [--domain N]           what the DDS mediators on a domain say of their ports\n"
    "  test   SPEC... [options]      run the specs' `test` declarations in simulated time\n"
    "  docs   SPEC [-o DIR]          Markdown, Graphviz DOT and SVG, Mermaid\n"
    "  import yarp APP.xml -o SPEC   a yarpmanager application and its Lua monitors as a spec\n"
    "  lsp                           a language server for editors, on stdin/stdout\n"
    "\n"
    "`arbc <command> --help` describes a command's options.\n"
    "exit codes: 0 fine, 1 refuted or unknown, 2 bad input, 3 run-time failure\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace arbc::cli;
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return kExitBadInput;
  }
  std::string_view command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::fputs(kUsage, stdout);
    return kExitOk;
  }
  if (command == "--version") {
    std::printf("arbc %s\n", ARBC_VERSION);
    return kExitOk;
  }
  std::span<char*> args(argv + 1, static_cast<size_t>(argc - 1));
  // verify and build create a Z3 context (build unless --no-verify: reserving costs nothing
  // until the pages are touched).
  bool will_prove = command == "verify" || command == "build";
  reserve_heap_for_spec(input_file_bytes(args), will_prove);
  // The process ends with these commands: their large results need not be freed.
  if (command == "check" || command == "build") process_ends_after_command();
  try {
    if (command == "check") return check_command(args);
    if (command == "verify") return verify_command(args);
    if (command == "build") return build_command(args);
    if (command == "run") return run_command(args);
    if (command == "test") return test_command(args);
    if (command == "docs") return docs_command(args);
    if (command == "import") return import_command(args);
    if (command == "lsp") return lsp_command(args);
    if (command == "status") return status_command(args);
  } catch (const std::exception& e) {
    // A bug, not a user error: say so plainly rather than dying on a signal.
    std::fprintf(stderr, "arbc: internal error: %s\n", e.what());
    return kExitRuntimeFailure;
  }
  // A misspelt command (`verfy`) is named with the one meant, above the usage.
  std::string hint;
  if (auto meant = arbc::closest_name(
          command, {"check", "verify", "build", "run", "status", "test", "docs", "import", "lsp"}))
    hint = ": did you mean '" + *meant + "'?";
  std::fprintf(stderr, "arbc: unknown command '%s'%s\n\n%s", argv[1], hint.c_str(), kUsage);
  return kExitBadInput;
}
