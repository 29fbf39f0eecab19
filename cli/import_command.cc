// `arbc import yarp APP.xml -o app.spec`: a yarpmanager application as a spec whose rules run
// the original Lua monitors (docs/yarp.md#moving-to-a-spec).
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/parse_error.h"
#include "core/diagnostic.h"
#include "import/yarp/spec_writer.h"
#include "import/yarp/yarp_import.h"

namespace arbc::cli {
namespace {

constexpr const char* kDescription =
    "Write a spec equivalent to an application written for another middleware. `yarp`: a\n"
    "yarpmanager application XML and its Lua port monitors; rules become `script` rules that\n"
    "run the original monitors (docs/yarp.md). YARP hazards are reported as warnings.\n"
    "Exit codes: 0 written, 2 bad input.";

}  // namespace

int import_command(std::span<char*> args) {
  CLI::App cli(kDescription, "arbc import");
  std::string kind, input, output;
  std::vector<std::string> search_paths;
  cli.add_option("kind", kind, "what to import: yarp")->required()->check(CLI::IsMember({"yarp"}));
  cli.add_option("input", input, "the yarpmanager application XML")->required();
  cli.add_option("-o,--output", output, "the spec to write")->required();
  cli.add_option("--yarp-path", search_paths,
                 "a folder to search for the Lua monitors the carriers name (repeatable)");
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(cli, e);
  }
  yarp::YarpImport im = yarp::import_yarp(input, {search_paths});
  SourceCache sources;
  for (Diagnostic d : im.diagnostics) {
    if (im.ok && d.severity == Severity::Error) d.severity = Severity::Warning;  // still written
    std::fputs(render(d, &sources).c_str(), stderr);
  }
  if (!im.ok) {
    std::fprintf(stderr, "arbc import: %s: nothing written (fix the errors above)\n",
                 input.c_str());
    return kExitBadInput;
  }
  std::vector<Diagnostic> renamed;
  std::string spec = yarp::write_spec(im, output, renamed);
  for (const Diagnostic& d : renamed) std::fputs(render(d, &sources).c_str(), stderr);
  errno = 0;
  std::ofstream out(output, std::ios::binary);
  out << spec;
  if (!out.flush()) {
    // Say why (most often: -o names a folder that does not exist), as `arbc run --report` does.
    std::fprintf(stderr, "arbc import: cannot write %s: %s\n", output.c_str(),
                 errno ? std::strerror(errno) : "write failed");
    return kExitBadInput;
  }
  size_t n = im.app.connections.size();
  std::fprintf(stderr, "arbc import: wrote %s (%zu connection%s)\n", output.c_str(), n,
               n == 1 ? "" : "s");
  return kExitOk;
}

}  // namespace arbc::cli
