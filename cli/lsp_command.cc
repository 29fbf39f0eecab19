// `arbc lsp`: the language server on stdin/stdout (docs/cli.md#arbc-lsp, docs/editors.md).
// Exit 0 after the client's shutdown and exit, 1 when the input ends without them, the client
// stops reading or its process is gone (as the LSP specifies), 2 on bad options.
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdlib>
#include <iostream>

#include "cli/commands.h"
#include "cli/duration_option.h"
#include "cli/msg_path_option.h"
#include "cli/parse_error.h"
#include "harness/monitor_runner.h"
#include "harness/test_replayer.h"
#include "lsp/server.h"

namespace arbc::cli {

int lsp_command(std::span<char*> args) {
  CLI::App app{
      "Serve the Language Server Protocol on stdin/stdout for editors: diagnostics as you type,\n"
      "the proof on save, hover, go to definition, references, outline, completion, quick fixes\n"
      "and rename. Messages go to stdout; what went wrong (a malformed message, a client\n"
      "gone) goes to stderr; what the server did (each proof's summary) goes to the client's\n"
      "log as window/logMessage."};
  app.name("arbc lsp");
  lsp::ServerOptions options;
  options.version = ARBC_VERSION;
  bool no_verify = false;
  bool stdio = true;
  app.add_flag("--stdio", stdio,
               "talk over stdin/stdout (the default; accepted for clients "
               "that pass it)");
  app.add_flag("--no-verify", no_verify, "do not prove documents on open and save");
  std::vector<std::string> msg_path;
  add_msg_path_option(app, &msg_path);
  app.add_option("--timeout", options.verify_timeout_seconds,
                 "seconds the proof of one document may take (or a time with its unit: 2min)")
      ->transform(seconds_option(false))
      ->type_name("DURATION")
      ->capture_default_str();
  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(app, e);
  }
  options.verify = !no_verify;
  // Counterexamples are replayed as `arbc verify` replays them, from the text being proved:
  // a violation over time is then confirmed on the runtime, not left unknown.
  options.make_replayers = [](std::shared_ptr<const lower::LoweredApp> lowered) {
    return lsp::Replayers{std::make_unique<harness::LuaMonitorRunner>(lowered),
                          std::make_unique<harness::RuntimeTestReplayer>(lowered)};
  };
  // A client that goes away closes our stdout: writes then fail (the server sees it and
  // exits 1) instead of killing the process with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  // A client whose process is gone: nothing is left to save, the workers may be mid-proof.
  options.on_client_gone = [] {
    std::cerr.flush();
    std::_Exit(1);  // as the LSP asks of an exit without `shutdown`
  };
  std::ios::sync_with_stdio(false);
  lsp::Server server(std::cin, std::cout, std::cerr, options);
  return server.run();
}

}  // namespace arbc::cli
