// `arbc import yarp APP.xml -o app.spec`: a yarpmanager application as a spec whose rules run
// the original Lua monitors (docs/yarp.md#moving-to-a-spec). `arbc import ros2-msg FILE.msg|DIR
// -o types.spec`: ROS 2 message definitions as `type` declarations (docs/language.md). `arbc
// import twist_mux FILE.yaml... -o mux.spec [--deploy mux.deploy.json]`: a twist_mux
// configuration as a spec, its properties and tests (docs/twist_mux.md).
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/parse_error.h"
#include "core/diagnostic.h"
#include "import/ros2/msg_import.h"
#include "import/twist_mux/twist_mux_config.h"
#include "import/twist_mux/twist_mux_spec.h"
#include "import/yarp/spec_writer.h"
#include "import/yarp/yarp_import.h"

namespace arbc::cli {
namespace {

constexpr const char* kDescription =
    "Write a spec equivalent to an application written for another middleware. `yarp`: a\n"
    "yarpmanager application XML and its Lua port monitors; rules become `script` rules that\n"
    "run the original monitors (docs/yarp.md). YARP hazards are reported as warnings.\n"
    "`ros2-msg`: ROS 2 .msg files (one, a package's or a folder of packages') as `type`\n"
    "declarations, the records `use ros2` declares (docs/language.md).\n"
    "`twist_mux`: twist_mux parameter files (its topics and locks, ROS 1 or ROS 2 form) as a\n"
    "spec with the properties and tests a twist_mux user relies on (docs/twist_mux.md).\n"
    "Exit codes: 0 written, 2 bad input.";

// Writes `text` to `output`; false (said on stderr) when it cannot.
bool write_output(const std::string& output, const std::string& text) {
  errno = 0;
  std::ofstream out(output, std::ios::binary);
  out << text;
  if (out.flush()) return true;
  // Say why (most often: -o names a folder that does not exist), as `arbc run --report` does.
  std::fprintf(stderr, "arbc import: cannot write %s: %s\n", output.c_str(),
               errno ? std::strerror(errno) : "write failed");
  return false;
}

int import_ros2_msg(const std::string& input, const std::string& output) {
  ros2_import::MsgImport im = ros2_import::import_ros2_messages(input);
  SourceCache sources;
  for (const Diagnostic& d : im.diagnostics) std::fputs(render(d, &sources).c_str(), stderr);
  if (!im.ok) {
    std::fprintf(stderr, "arbc import: %s: nothing written (fix the errors above)\n",
                 input.c_str());
    return kExitBadInput;
  }
  if (!write_output(output, im.spec)) return kExitBadInput;
  std::fprintf(stderr, "arbc import: wrote %s\n", output.c_str());
  return kExitOk;
}

int import_twist_mux(const std::vector<std::string>& inputs, const std::string& output,
                     const std::string& deploy, const std::string& output_topic) {
  twist_mux::MuxConfig config = twist_mux::read_twist_mux(inputs);
  SourceCache sources;
  for (const Diagnostic& d : config.diagnostics) std::fputs(render(d, &sources).c_str(), stderr);
  if (!config.ok) {
    std::fprintf(stderr, "arbc import: nothing written (fix the errors above)\n");
    return kExitBadInput;
  }
  std::string names;
  for (const std::string& f : inputs)
    names += (names.empty() ? "" : ", ") + std::filesystem::path(f).filename().string();
  twist_mux::MuxSpec spec = twist_mux::write_mux_spec(config, names, output_topic);
  for (const Diagnostic& d : spec.warnings) std::fputs(render(d, &sources).c_str(), stderr);
  if (!write_output(output, spec.spec)) return kExitBadInput;
  if (!deploy.empty() && !write_output(deploy, spec.deploy)) return kExitBadInput;
  std::fprintf(stderr, "arbc import: wrote %s%s%s\n", output.c_str(), deploy.empty() ? "" : " and ",
               deploy.c_str());
  return kExitOk;
}

}  // namespace

int import_command(std::span<char*> args) {
  CLI::App cli(kDescription, "arbc import");
  std::string kind, output, deploy, output_topic = "cmd_vel_out";
  std::vector<std::string> inputs;
  std::vector<std::string> search_paths;
  cli.add_option("kind", kind, "what to import: yarp, ros2-msg or twist_mux")
      ->required()
      ->check(CLI::IsMember({"yarp", "ros2-msg", "twist_mux"}));
  cli.add_option("input", inputs,
                 "yarp: the yarpmanager application XML; ros2-msg: a .msg file or a folder; "
                 "twist_mux: its parameter files (topics, locks)")
      ->required();
  cli.add_option("-o,--output", output, "the spec to write")->required();
  cli.add_option("--yarp-path", search_paths,
                 "a folder to search for the Lua monitors the carriers name (repeatable)");
  cli.add_option("--deploy", deploy,
                 "twist_mux: also write the DDS deployment file (ROS 2 topic names)");
  cli.add_option("--output-topic", output_topic,
                 "twist_mux: the topic it publishes on (default cmd_vel_out)");
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(cli, e);
  }
  if (kind == "twist_mux") return import_twist_mux(inputs, output, deploy, output_topic);
  if (inputs.size() != 1) {
    std::fprintf(stderr, "arbc import %s: one input file, not %zu\n", kind.c_str(), inputs.size());
    return kExitBadInput;
  }
  const std::string& input = inputs.front();
  if (kind == "ros2-msg") return import_ros2_msg(input, output);
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
  if (!write_output(output, spec)) return kExitBadInput;
  size_t n = im.app.connections.size();
  std::fprintf(stderr, "arbc import: wrote %s (%zu connection%s)\n", output.c_str(), n,
               n == 1 ? "" : "s");
  return kExitOk;
}

}  // namespace arbc::cli
