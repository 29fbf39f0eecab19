// `arbc run DIR|SPEC [--plugin LIB]... [--scenario NAME] [--duration D] [--realtime]
//                    [--seed N] [--trace FILE] [--report FILE.html] [--no-verify] [--state FILE]
//                    [--transport inproc|dds] [--host ..] [--mediate ..] [--deploy FILE]
//                    [--domain N] [--time-scale K]  (these six: cli/run_transport.h)
//                    [--inputs FILE] [--stub] [--stub-rate PORT=HZ]... [--diff TRACE]`
// Runs a built application on the embedded runtime (docs/runtime.md), prints the
// per-connection counters and the environment's verdict. Exit: 0 success, 2 bad input,
// 3 run-time failure (the environment reports failure, or, with no environment, a connection
// was quarantined). The app is proved first, unless --no-verify (said in the output and the
// report): a SPEC is built and verified into a temporary directory by `arbc build`, a DIR is
// verified here; a refuted or unknown proof exits 1, and nothing runs. A DIR whose monitors
// differ from the digests in its app.json is bad input. --report writes an HTML page about the
// run (report/run_report.h) from the trace records kept in memory. Ctrl-C and SIGTERM end
// the run within a second (cli/run_interrupt.h).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/parse_error.h"
#include "cli/run_end.h"
#include "cli/run_interrupt.h"
#include "cli/run_options.h"
#include "cli/run_stand_ins.h"
#include "cli/run_status.h"
#include "cli/run_transport.h"
#include "cli/verify_gate.h"
#include "core/diagnostic.h"
#include "core/join.h"
#include "report/report_file.h"
#include "runtime/app_loader.h"
#include "runtime/runtime.h"
#include "verify/proof_record.h"

namespace arbc::cli {

namespace {

namespace fs = std::filesystem;

// After a signal, how long the run may take to return before the watchdog gives up on it: a
// stuck callback is then named and the process ends, within a second of the signal in all.
constexpr double kStuckGrace = 0.6;
// ... and how much longer closing the transport may take: Fast-DDS deletes each reader, writer
// and the participant in turn (21 topics took over 0.6 s under ASan on a loaded CI machine).
constexpr double kTransportCloseGrace = 10;

// A temporary directory removed when the run ends.
struct TempDir {
  std::string path;
  ~TempDir() {
    std::error_code ignored;
    if (!path.empty()) fs::remove_all(path, ignored);
  }
};

// Builds (and, unless no_verify, verifies) a spec into `temp` as `arbc build` does, and
// returns the app directory it wrote. Returns the build's exit code on failure (1 refuted, 2 bad
// input; its diagnostics are already printed).
int build_spec_into(const std::string& spec, bool no_verify, TempDir* temp, std::string* dir) {
  std::string pattern = (fs::temp_directory_path() / "arbc-run-XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    std::fprintf(stderr, "arbc run: error: cannot create a temporary directory for the build\n");
    return kExitRuntimeFailure;
  }
  temp->path = pattern;
  BuildRequest request;
  request.spec = spec;
  request.out_dir = temp->path;
  request.no_verify = no_verify;
  return build_spec(request, dir);
}

// Turns the command's input into a built app directory: a directory is used as is, a spec is
// built first. Returns an exit code (kExitOk: *dir is ready).
int prepare_app_dir(const std::string& input, bool no_verify, TempDir* temp, std::string* dir) {
  if (fs::is_directory(input)) {
    *dir = input;
    return kExitOk;
  }
  if (fs::path(input).filename() == "app.json" && fs::is_regular_file(input)) {
    *dir = fs::path(input).parent_path().string();  // as `arbc verify` and `arbc docs` take it
    if (dir->empty()) *dir = ".";
    return kExitOk;
  }
  if (fs::path(input).extension() == ".spec") return build_spec_into(input, no_verify, temp, dir);
  std::fprintf(stderr,
               "arbc run: error: %s: not an app directory (one with app.json and monitors/, "
               "written by `arbc build`), its app.json, nor a .spec file\n",
               input.c_str());
  return kExitBadInput;
}

void print_errors(const std::vector<std::string>& errors) {
  for (const std::string& e : errors) std::fprintf(stderr, "arbc run: error: %s\n", e.c_str());
}

// The same for an error of one line per problem.
void print_errors(const std::string& lines) {
  std::istringstream in(lines);
  for (std::string line; std::getline(in, line);) print_errors(std::vector<std::string>{line});
}

std::string app_json_bytes(const std::string& dir) {
  std::ifstream in(fs::path(dir) / "app.json", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Proves the app before it runs, as `arbc build` does (or finds that the build's proof of this
// very app.json holds, verify/proof_record.h), and sets *proof to what the output and
// the report say about it (a spec was proved when it was built, and the build's summary said
// so). Returns an exit code: kExitOk to run, else the proof's (1 refuted or unknown, 2 a
// malformed model).
int prove_app_dir(const model::App& app, const std::string& dir, bool built_from_spec,
                  bool no_verify, std::string* proof) {
  if (no_verify) {
    *proof = "not verified (--no-verify)";
  } else if (built_from_spec) {
    *proof = verified_summary(app.arbitrated_ports);
  } else if (std::optional<std::string> recorded =
                 verify::recorded_proof(dir, app_json_bytes(dir))) {
    *proof = *recorded + " (by arbc build, for this very app.json)";
  } else {
    SourceCache sources;
    VerifyGate gate = verify_before_writing(
        app, (fs::path(dir) / "app.json").string(), &sources, /*strict=*/false,
        "nothing was run (fix the spec and rebuild, or run anyway with --no-verify)", "arbc run");
    if (!gate.pass) return gate.exit_code;
    *proof = gate.summary;
  }
  if (!built_from_spec) std::printf("%s\n", proof->c_str());
  return kExitOk;
}

// The command line of `arbc run`.
struct RunArgs {
  std::string input;
  std::vector<std::string> plugins;
  bool no_verify = false;
  RunOptions options;
  std::string report_path;
  std::string runtime_checks = "fail";  // --runtime-checks: stop, fail, warn or off
  bool status = false;                  // --status: the live view on standard error
  TransportFlags transport;             // --transport, --host, --mediate, ... (cli/run_transport.h)
  RunStandIns stand_ins;                // --inputs, --stub, --stub-rate, --diff
};

// Parses `arbc run`'s arguments into `a`; an exit code when the command ends here (--help,
// a bad option or value).
std::optional<int> parse_args(std::span<char*> args, RunArgs& a) {
  CLI::App cli{"Run a built application on the embedded runtime", "arbc run"};
  std::string duration_text = "60s";
  RunOptions& options = a.options;
  cli.add_option("app", a.input,
                 "an app directory written by `arbc build`, its app.json, or a .spec")
      ->required();
  cli.add_option("--plugin", a.plugins, "a shared library with modules (repeatable)");
  cli.add_option("--scenario", options.scenario, "scenario name passed to the environment");
  cli.add_option("--duration", duration_text, "how long to run: 60s, 500ms, 2min, 3h (default 60s)")
      ->type_name("DURATION");
  cli.add_flag("--no-verify", a.no_verify,
               "run without the proof (a SPEC is built without it, a DIR is not verified)");
  cli.add_flag("--realtime", options.realtime, "run on the wall clock instead of simulated time");
  std::string seed_text = "1";
  cli.add_option("--seed", seed_text, "seed of every random generator (default 1)")
      ->type_name("UINT");
  cli.add_option("--trace", options.trace_path, "write a JSON-lines trace to FILE");
  cli.add_option("--runtime-checks", a.runtime_checks,
                 "what a run that breaks a proved property or an assumption of the proof does: "
                 "stop (end the run there, exit 3), fail (exit 3 at its end, the default), warn "
                 "(said, verdict kept) or off")
      ->check(CLI::IsMember({"stop", "fail", "warn", "off"}));
  cli.add_option("--state", options.state_path,
                 "keep this mediator's memory of its own deliveries in FILE, so that one started "
                 "again goes on from it (docs/runtime.md#a-mediator-that-restarts)")
      ->type_name("FILE");
  cli.add_option("--report", a.report_path,
                 "write a self-contained HTML report of the run to FILE");
  cli.add_flag("--status", a.status,
               "show each arbitrated port's selected rule, why the others are not selected, and "
               "its counters on standard error, redrawn every 250ms of run time");
  add_transport_options(cli, &a.transport);
  a.stand_ins.add_options(cli);  // --inputs, --stub, --stub-rate, --diff
  try {
    cli.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return exit_for_parse_error(cli, e);
  }
  std::string value_error;
  if (!parse_run_duration(duration_text, &options.duration, &value_error) ||
      !parse_seed(seed_text, &options.seed, &value_error)) {
    std::fprintf(stderr, "arbc run: error: %s\n", value_error.c_str());
    return kExitBadInput;
  }
  return std::nullopt;
}

// Loads each --plugin library; false (the error printed) when one cannot be loaded.
bool load_plugins(const std::vector<std::string>& plugins) {
  for (const std::string& lib : plugins) {
    std::string error;
    if (!load_plugin(lib, &error)) {
      print_errors({lib + ": " + error});
      return false;
    }
  }
  print_errors(Registry::global().errors());
  return true;
}

// A spec tried before its C++ exists names modules no plugin provides: the way to run it
// anyway is --stub (docs/testing.md), which a newcomer cannot guess from "load the plugin".
void print_stand_in_hint(const model::App& app, const Registry& registry, const ModuleSet& host) {
  std::vector<std::string> missing;
  for (const model::Module& m : app.modules) {
    if (host.contains(m.name) && !registry.find_module(m.name)) missing.push_back(m.name);
  }
  if (missing.empty()) return;
  std::fprintf(stderr,
               "arbc run: note: to try the app without C++ for %s, add --stub: modules no "
               "plugin provides run as stand-ins (a source publishes samples of its type, a "
               "sink records what reaches it; docs/testing.md)\n",
               join(missing, ", ", " and ").c_str());
}

// A mediator in another process than its modules may be stopped and started again while
// the world goes on; what its deliveries set is then lost unless it keeps a memory
// (docs/runtime.md#a-mediator-that-restarts). Said once, at start, where it matters.
void note_memory(const model::App& app, const RunOptions& options) {
  if (!options.state_path.empty() || !options.transport) return;  // in-process: no restart
  const ModuleSet& mediated = options.mediate ? *options.mediate : options.host;
  std::set<std::string> kept;
  for (const model::Connection& c : app.connections) {
    if (!mediated.contains(std::string_view(c.destination).substr(0, c.destination.find('.'))))
      continue;
    const model::Port* from = app.find_port(c.source);
    if (c.kind == model::ConnectionKind::Feed && from && from->direction == model::Direction::In)
      kept.insert(c.sets.begin(), c.sets.end());
    if (!c.activity_event.empty()) kept.insert(c.activity_event);
    kept.insert(c.delivery_sets.begin(), c.delivery_sets.end());
  }
  if (kept.empty()) return;
  std::fprintf(stderr,
               "arbc run: note: what this mediator's deliveries set (%s) starts afresh if it is "
               "started again; give --state FILE to keep it across restarts "
               "(docs/runtime.md#a-mediator-that-restarts)\n",
               join(std::vector<std::string>(kept.begin(), kept.end()), ", ").c_str());
}

// The runtime checks see every trace record, start with the run, and keep their share of a
// mediator's memory (--state).
// `stop`: not null, the run to end at the first breach (set once the runtime exists).
void watch_claims(ClaimWatch& claims, RunOptions& options, Runtime** stop) {
  options.trace_watch = [&claims, stop](const TraceLine& r, Trace& trace) {
    size_t before = claims.violations().size();
    claims.watch(r, trace);
    if (stop && *stop && before == 0 && !claims.violations().empty())
      (*stop)->request_stop("runtime check broken: " + claims.violations()[0].claim);
  };
  options.on_start = [&claims](Nanos t) { claims.start(t); };
  options.on_finish = [&claims](Nanos end, Trace& trace) { claims.finish(end, &trace); };
  options.checks_memory = {
      [&claims] { return claims.save(); },
      [&claims](const nlohmann::json& j, std::string* e) { return claims.load(j, e); },
      [&claims](Nanos shift) { claims.resume(shift); }};
}

// Opens --report's file before the run (a path that cannot be written is bad input, said before
// anything runs); false after saying why. No --report: nothing to open.
bool open_report(const std::string& path, report::ReportFile* file) {
  std::string error;
  if (path.empty() || file->open(path, &error)) return true;
  print_errors({error});
  return false;
}

}  // namespace

// The app of `dir`; nullopt after printing why it does not load (an error in app.json's text
// rendered as a compiler's, its line quoted).
std::optional<model::App> load_app_or_say_why(const std::string& dir) {
  std::string load_error;
  Diagnostic app_json_error;
  std::optional<model::App> loaded = load_app_dir(dir, &load_error, &app_json_error);
  if (loaded) return loaded;
  if (app_json_error.loc.file.empty()) {
    print_errors(load_error);
  } else {
    SourceCache sources;
    std::fputs(render(app_json_error, &sources).c_str(), stderr);
  }
  return std::nullopt;
}

// The plugins' modules against app.json's (what each provides, their ports' types); false after
// saying what differs.
static bool modules_match(const model::App& app, const std::string& dir, RunStandIns& stand_ins,
                          const RunOptions& options) {
  std::vector<std::string> mismatches =
      check_modules(app, (fs::path(dir) / "app.json").string(), stand_ins.registry(), options.host);
  if (mismatches.empty()) return true;
  print_errors(mismatches);
  print_stand_in_hint(app, stand_ins.registry(), options.host);
  return false;
}

int run_command(std::span<char*> args) {
  RunArgs a;
  if (std::optional<int> exit = parse_args(args, a)) return *exit;
  RunOptions& options = a.options;
  RunStandIns& stand_ins = a.stand_ins;
  if (!load_plugins(a.plugins)) return kExitBadInput;

  std::string dir, error;
  TempDir temp;
  int prepared = prepare_app_dir(a.input, a.no_verify, &temp, &dir);
  if (prepared != kExitOk) return prepared;
  std::optional<model::App> loaded = load_app_or_say_why(dir);
  if (!loaded) return kExitBadInput;
  const model::App& app = *loaded;
  int placed = apply_transport(a.transport, app, &options);
  if (placed != kExitOk) return placed;
  note_memory(app, options);
  if (!stand_ins.prepare(app, options.duration, &error)) {
    print_errors({error});
    return kExitBadInput;
  }
  if (!modules_match(app, dir, stand_ins, options)) return kExitBadInput;
  std::string proof;
  int proved = prove_app_dir(app, dir, /*built_from_spec=*/!temp.path.empty(), a.no_verify, &proof);
  if (proved != kExitOk) return proved;
  std::vector<TraceRecord> records;  // the whole trace in memory, for --report
  if (!a.report_path.empty() || stand_ins.wants_records()) options.trace_records = &records;
  // What the proof proved and assumed, checked on every record of the ports mediated here.
  ClaimWatch claims(app, {.mediated = options.mediate ? *options.mediate : options.host,
                          .hosted = options.host,
                          .states_known = !options.unknown_until_fed});
  if (!claims.load_claims(dir, &error)) {
    print_errors({error});
    return kExitBadInput;
  }
  bool watching = !claims.empty() && a.runtime_checks != "off";
  Runtime* stop_on_breach = nullptr;  // --runtime-checks stop: the runtime, once created
  if (watching)
    watch_claims(claims, options, a.runtime_checks == "stop" ? &stop_on_breach : nullptr);
  StatusBoard board = StatusBoard::for_stderr();
  if (a.status) board.attach(options);
  RunInterrupt interrupt;  // from here on Ctrl-C and SIGTERM end the run, not the process
  options.interrupt = interrupt.flag();
  // Errors about app.json's content name it; the others (a plugin, a monitor, the trace file,
  // DDS) name what they are about: "out/app/app.json: DDS: ..." sent users to the wrong file.
  options.app_file = (fs::path(dir) / "app.json").string();
  std::unique_ptr<Runtime> runtime =
      Runtime::create(app, dir, options, &error, stand_ins.registry());
  if (!runtime) {
    print_errors(error);
    return kExitBadInput;
  }
  stop_on_breach = runtime.get();
  report::ReportFile report_file;
  if (!open_report(a.report_path, &report_file)) return kExitBadInput;

  RunEnd end{app,           *runtime,    options, records,
             a.report_path, report_file, proof,   describe_transport(a.transport, options)};
  if (stand_ins.active()) end.stand_ins = [&] { return stand_ins.summary(app); };
  if (watching) end.claims = &claims;
  end.claims_fail = a.runtime_checks == "fail" || a.runtime_checks == "stop";
  auto patience = [&] {
    return end.runtime.busy().kind == "transport" ? kTransportCloseGrace : 0.0;
  };
  interrupt.watch(kStuckGrace, patience, [&](double waited) {
    give_up_stuck_run(end, interrupt.signal_name(), waited);
    std::error_code ignored;
    if (!temp.path.empty()) fs::remove_all(temp.path, ignored);  // no destructor runs now
  });
  runtime->run();
  if (!interrupt.run_returned()) {
    for (;;) pause();  // the watchdog is ending the process
  }
  return stand_ins.diff(app, records, finish_run(end, interrupt.signal_name()));
}

}  // namespace arbc::cli
