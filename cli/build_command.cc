// `arbc build SPEC [-o DIR] [--target embedded] [--no-verify]` (docs/cli.md#arbc-build):
// compile the spec, prove it, then write DIR/<app>/app.json and DIR/<app>/monitors/*.lua.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "cli/build_summary.h"
#include "cli/commands.h"
#include "cli/verify_gate.h"
#include "compiler/codegen/target.h"
#include "compiler/codegen/write_artifacts.h"
#include "compiler/frontend/frontend.h"
#include "compiler/lower/compile_spec.h"

namespace arbc::cli {

namespace {

std::string target_list() {
  std::string out;
  for (const std::string& t : codegen::target_names()) out += (out.empty() ? "" : ", ") + t;
  return out;
}

}  // namespace

int build_command(std::span<char*> args) {
  CLI::App cli{
      "Compile a behaviour spec, prove that each arbitrated port selects at most one rule, and "
      "write DIR/<app>/app.json and one Lua monitor per connection under DIR/<app>/monitors/.\n"
      "Nothing is written when the proof fails (exit 1) or the spec has errors (exit 2).",
      "arbc build"};
  std::string spec;
  std::string out_dir = "out";
  std::string target_name(codegen::kDefaultTarget);
  bool no_verify = false;
  bool strict = false;
  bool stats = false;
  cli.add_option("SPEC", spec, "the spec file, e.g. specs/table_clean.spec")->required();
  cli.add_option("-o,--output", out_dir, "directory to write DIR/<app>/ into")->default_val("out");
  cli.add_option("--target", target_name, "code-generation target: " + target_list())
      ->default_val(std::string(codegen::kDefaultTarget));
  cli.add_flag("--no-verify", no_verify, "write the artifacts without running the proof");
  cli.add_flag("--strict", strict, "verifier warnings (dead, unused rules) stop the build too");
  cli.add_flag("--stats", stats, "print the time each phase took to stderr");
  try {
    std::vector<std::string> rest;
    for (size_t i = args.size(); i > 1; --i) rest.emplace_back(args[i - 1]);
    cli.parse(rest);
  } catch (const CLI::ParseError& e) {
    int code = cli.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }

  std::unique_ptr<codegen::Target> target = codegen::make_target(target_name);
  if (!target) {
    std::fprintf(stderr, "arbc build: unknown target '%s'; the targets are: %s\n",
                 target_name.c_str(), target_list().c_str());
    return kExitBadInput;
  }

  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  std::clock_t c0 = std::clock();
  auto phase = [&](const char* name) {
    auto t = Clock::now();
    std::clock_t c = std::clock();
    if (stats)
      std::fprintf(stderr, "arbc build: %-8s %.3f s wall, %.3f s cpu\n", name,
                   std::chrono::duration<double>(t - t0).count(),
                   static_cast<double>(c - c0) / CLOCKS_PER_SEC);
    t0 = t;
    c0 = c;
  };
  lower::CompiledSpec compiled = lower::compile_spec(spec);
  phase("compile");
  std::fputs(frontend::render_diagnostics(compiled.diagnostics, &compiled.sources).c_str(), stderr);
  if (!compiled.ok) {
    std::fprintf(stderr, "arbc build: %s has errors; nothing was written\n", spec.c_str());
    return kExitBadInput;
  }
  const lower::LoweredApp& lowered = *compiled.lowered;

  std::string verified = "not verified (--no-verify)";
  if (!no_verify) {
    VerifyGate gate = verify_before_writing(lowered.app, spec, &compiled.sources, strict);
    if (!gate.pass) return gate.exit_code;
    verified = gate.summary;
    phase("verify");
  }

  codegen::CodegenResult generated = target->generate(lowered);
  phase("generate");
  for (const Diagnostic& d : generated.diagnostics)
    std::fputs(render(d, &compiled.sources).c_str(), stderr);
  if (!generated.ok) {
    std::fprintf(stderr, "arbc build: code generation failed; nothing was written\n");
    return kExitRuntimeFailure;
  }
  std::string error = codegen::write_artifacts(out_dir, lowered.app.name, generated.files);
  if (!error.empty()) {
    std::fprintf(stderr, "arbc build: %s\n", error.c_str());
    return kExitBadInput;
  }
  phase("write");
  std::fputs(build_summary(lowered.app, spec, out_dir, verified).c_str(), stdout);
  return kExitOk;
}

}  // namespace arbc::cli
