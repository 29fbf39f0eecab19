// `arbc build SPEC [-o DIR] [--target embedded|yarp] [--deploy FILE] [--no-verify]`
// (docs/cli.md#arbc-build): compile the spec, prove it, then write DIR/<app>/: app.json and
// monitors/*.lua, or for YARP the application XML, its monitors and ports.json (docs/yarp.md).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/build_summary.h"
#include "cli/commands.h"
#include "cli/left_at_exit.h"
#include "cli/msg_path_option.h"
#include "cli/parse_error.h"
#include "cli/verify_gate.h"
#include "compiler/codegen/target.h"
#include "compiler/codegen/write_artifacts.h"
#include "compiler/codegen/yarp_deployment.h"
#include "compiler/codegen/yarp_filled_modules.h"
#include "compiler/frontend/frontend.h"
#include "compiler/lower/compile_spec.h"
#include "core/diagnostic.h"
#include "core/join.h"
#include "core/suggest.h"
#include "verify/proof_record.h"

namespace arbc::cli {

namespace {

std::string target_list() { return join(codegen::target_names()); }

// Parses `arbc build`'s arguments into `a`; an exit code when the command ends here (--help,
// a bad option).
std::optional<int> parse_args(std::span<char*> args, BuildRequest& a) {
  CLI::App cli{
      "Compile a behaviour spec, prove that each arbitrated port selects at most one rule (by "
      "priority: that a rule's delivery holds every rule below it off for its hold), and "
      "write DIR/<app>/app.json and one Lua monitor per connection under DIR/<app>/monitors/\n"
      "(--target yarp: DIR/<app>/<app>.xml, ports.json and contexts/<app>/*.lua for YARP).\n"
      "Nothing is written when the proof fails (exit 1) or the spec has errors (exit 2).",
      "arbc build"};
  cli.add_option("SPEC", a.spec, "the spec file, e.g. specs/table_clean.spec")->required();
  std::vector<std::string> msg_path;
  add_msg_path_option(cli, &msg_path);
  cli.add_option("-o,--output", a.out_dir, "directory to write DIR/<app>/ into")
      ->default_val("out");
  cli.add_option("--target", a.target_name, "code-generation target: " + target_list())
      ->default_val(std::string(codegen::kDefaultTarget));
  cli.add_option("--deploy", a.deploy,
                 "deployment file (JSON); --target yarp reads its \"topics\": "
                 "{\"Module.port\": \"/yarp/name\"}");
  cli.add_flag("--no-verify", a.no_verify, "write the artifacts without running the proof");
  cli.add_flag("--strict", a.strict, "verifier warnings (dead, unused rules) stop the build too");
  cli.add_flag("--stats", a.stats, "print the time each phase took to stderr");
  try {
    std::vector<std::string> rest;
    for (size_t i = args.size(); i > 1; --i) rest.emplace_back(args[i - 1]);
    cli.parse(rest);
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(cli, e);
  }
  return std::nullopt;
}

// Under --stats, prints the wall and CPU time of each phase to stderr.
class PhaseTimer {
 public:
  explicit PhaseTimer(bool print) : print_(print) {}

  // Ends the phase `name` (started when the previous one ended) and starts the next.
  void phase(const char* name) {
    auto t = Clock::now();
    std::clock_t c = std::clock();
    if (print_)
      std::fprintf(stderr, "arbc build: %-8s %.3f s wall, %.3f s cpu\n", name,
                   std::chrono::duration<double>(t - t0_).count(),
                   static_cast<double>(c - c0_) / CLOCKS_PER_SEC);
    t0_ = t;
    c0_ = c;
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool print_;
  Clock::time_point t0_ = Clock::now();
  std::clock_t c0_ = std::clock();
};

// Reads the deployment file (if any) into the target's options; an exit code on bad input.
std::optional<int> configure_target(codegen::Target& target, const std::string& deploy,
                                    const model::App& app) {
  codegen::TargetOptions options;
  std::string error;
  if (!deploy.empty()) {
    std::vector<Diagnostic> problems;
    auto names = codegen::read_yarp_deployment(deploy, app, &problems);
    if (!names) {
      SourceCache sources;  // quotes the file's lines under each problem
      for (const Diagnostic& d : problems) std::fputs(render(d, &sources).c_str(), stderr);
      return kExitBadInput;
    }
    options.port_names = std::move(*names);
  }
  if (!target.configure(options, &error)) {
    std::fprintf(stderr, "arbc build: %s\n", error.c_str());
    return kExitBadInput;
  }
  return std::nullopt;
}

// The <module>s the user filled in (docs/yarp.md step 3) in the application XML this build
// replaces: kept in the new one, or dropped with their module from the spec; their names.
struct UserModules {
  std::vector<std::string> kept, dropped;
};

UserModules keep_user_modules(std::vector<codegen::OutputFile>& files, const std::string& app_dir,
                              const std::string& xml) {
  UserModules m;
  std::ifstream in(app_dir + "/" + xml, std::ios::binary);
  if (!in) return m;
  std::ostringstream previous;
  previous << in.rdbuf();
  for (codegen::OutputFile& f : files) {
    if (f.path == xml)
      f.content = codegen::keep_filled_modules(f.content, previous.str(), &m.kept, &m.dropped);
  }
  return m;
}

// A proved app.json gets its proof recorded beside it (verify/proof_record.h), so that `arbc run`
// of the directory need not prove the same bytes again. Targets without an app.json (yarp) run
// elsewhere and get none.
void record_proof(std::vector<codegen::OutputFile>& files, const std::string& summary) {
  for (const codegen::OutputFile& f : files) {
    if (f.path != "app.json") continue;
    std::string record = verify::proof_record(f.content, summary);
    if (!record.empty()) files.push_back({verify::kProofRecordFile, std::move(record)});
    return;
  }
}

}  // namespace

int build_command(std::span<char*> args) {
  BuildRequest a;
  if (std::optional<int> exit = parse_args(args, a)) return *exit;
  std::string app_dir;
  return build_spec(a, &app_dir);
}

int build_spec(const BuildRequest& a, std::string* app_dir) {
  const std::string& spec = a.spec;
  std::unique_ptr<codegen::Target> target = codegen::make_target(a.target_name);
  if (!target) {
    std::optional<std::string> meant = closest_name(a.target_name, codegen::target_names());
    std::fprintf(stderr, "arbc build: unknown target '%s'%s; the targets are: %s\n",
                 a.target_name.c_str(), meant ? (" (did you mean '" + *meant + "'?)").c_str() : "",
                 target_list().c_str());
    return kExitBadInput;
  }

  PhaseTimer timer(a.stats);
  lower::CompiledSpec compiled = lower::compile_spec(spec);
  timer.phase("compile");
  std::fputs(frontend::render_diagnostics(compiled.diagnostics, &compiled.sources).c_str(), stderr);
  if (!compiled.ok) {
    std::fprintf(stderr, "arbc build: %s has errors; nothing was written\n", spec.c_str());
    return kExitBadInput;
  }
  // A copy: the proof adds what the runtime must enforce of it (apply_list_bounds).
  lower::LoweredApp lowered = *compiled.lowered;
  if (std::optional<int> exit = configure_target(*target, a.deploy, lowered.app)) return *exit;

  std::string verified = "not verified (--no-verify)";
  if (!a.no_verify) {
    VerifyGate gate = verify_before_writing(lowered.app, spec, &compiled.sources, a.strict);
    if (!gate.pass) return gate.exit_code;
    verified = gate.summary;
    apply_list_bounds(gate, lowered.app);
    timer.phase("verify");
  }

  codegen::CodegenResult generated = target->generate(lowered);
  timer.phase("generate");
  for (const Diagnostic& d : generated.diagnostics)
    std::fputs(render(d, &compiled.sources).c_str(), stderr);
  if (!generated.ok) {
    std::fprintf(stderr, "arbc build: code generation failed; nothing was written\n");
    return generated.bad_input ? kExitBadInput : kExitRuntimeFailure;
  }
  UserModules user;
  if (a.target_name == "yarp")
    user = keep_user_modules(generated.files, a.out_dir + "/" + lowered.app.name,
                             lowered.app.name + ".xml");
  if (!a.no_verify) record_proof(generated.files, verified);
  std::string error;
  if (!codegen::write_artifacts(a.out_dir, lowered.app.name, generated.files, &error)) {
    std::fprintf(stderr, "arbc build: %s\n", error.c_str());
    return kExitBadInput;
  }
  timer.phase("write");
  *app_dir = a.out_dir + "/" + lowered.app.name;
  if (a.target_name == "yarp") {
    std::vector<std::string> paths;
    for (const codegen::OutputFile& f : generated.files) paths.push_back(f.path);
    std::fputs(yarp_build_summary(lowered.app, spec, a.out_dir, verified, paths).c_str(), stdout);
    if (!user.kept.empty())
      std::printf("  kept the <module>s you filled in for %s from the %s.xml it replaced\n",
                  join(user.kept).c_str(), lowered.app.name.c_str());
    if (!user.dropped.empty())
      std::fprintf(stderr,
                   "arbc build: warning: the replaced %s.xml had <module>s filled in for %s, "
                   "which the spec no longer has: they are not in the new one\n",
                   lowered.app.name.c_str(), join(user.dropped).c_str());
  } else {
    std::fputs(build_summary(lowered.app, spec, a.out_dir, verified).c_str(), stdout);
  }
  leave_at_exit(generated);
  leave_at_exit(compiled);
  return kExitOk;
}

}  // namespace arbc::cli
