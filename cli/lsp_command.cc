// `arbc lsp`: the language server on stdin/stdout (docs/cli.md#arbc-lsp, docs/editors.md).
// Exit 0 after the client's shutdown and exit, 1 when the input ends without them (as the LSP
// specifies), 2 on bad options.
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/commands.h"
#include "lsp/server.h"

namespace arbc::cli {

int lsp_command(std::span<char*> args) {
  CLI::App app{
      "Serve the Language Server Protocol on stdin/stdout for editors: diagnostics as you type,\n"
      "the proof on save, hover, go to definition, references, outline, completion, quick fixes\n"
      "and rename. Messages go to stdout; a log of what the server did goes to stderr."};
  app.name("arbc lsp");
  lsp::ServerOptions options;
  options.version = ARBC_VERSION;
  bool no_verify = false;
  bool stdio = true;
  app.add_flag("--stdio", stdio,
               "talk over stdin/stdout (the default; accepted for clients "
               "that pass it)");
  app.add_flag("--no-verify", no_verify, "do not prove documents on open and save");
  app.add_option("--timeout", options.verify_timeout_seconds,
                 "seconds the proof of one document may take")
      ->capture_default_str();
  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  options.verify = !no_verify;
  std::ios::sync_with_stdio(false);
  lsp::Server server(std::cin, std::cout, std::cerr, options);
  return server.run();
}

}  // namespace arbc::cli
