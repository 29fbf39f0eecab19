#include "compiler/codegen/embedded_target.h"

#include <exception>
#include <optional>
#include <thread>

#include "compiler/codegen/claims_writer.h"
#include "compiler/codegen/monitor_writer.h"
#include "compiler/frontend/lua_syntax.h"
#include "compiler/lower/lowered_app.h"
#include "core/app_json.h"
#include "core/check_ids.h"
#include "core/sha256.h"

namespace arbc::codegen {

namespace {

// Below this many monitors a second thread costs more than it saves.
constexpr size_t kMonitorsPerThread = 512;

struct GeneratedMonitor {
  MonitorText text;
  bool compiles = true;
  std::string lua_error;  // Lua's message when it does not compile
  std::string sha256;
};

// Writes, compiles and hashes the monitors of plans [begin, end) into the same places of `out`.
// Monitors are independent of each other: the two halves of a large app run on two threads.
void generate_monitors(const lower::LoweredApp& lowered, const SpecLines& lines, size_t begin,
                       size_t end, std::vector<std::optional<GeneratedMonitor>>& out) {
  frontend::LuaSyntaxChecker lua;  // one Lua state per thread
  for (size_t i = begin; i < end; ++i) {
    const lower::MonitorPlan& plan = lowered.monitors[i];
    const model::Connection& c = lowered.app.connections[plan.connection];
    if (c.monitor.empty()) continue;
    GeneratedMonitor g;
    g.text = write_monitor(lowered, plan, lines);
    g.compiles = lua.check(g.text.text, c.monitor, &g.lua_error);
    g.sha256 = sha256_hex(g.text.text);
    out[i] = std::move(g);
  }
}

std::vector<std::optional<GeneratedMonitor>> generate_all_monitors(const lower::LoweredApp& lowered,
                                                                   const SpecLines& lines) {
  size_t n = lowered.monitors.size();
  std::vector<std::optional<GeneratedMonitor>> out(n);
  if (n < 2 * kMonitorsPerThread || std::thread::hardware_concurrency() < 2) {
    generate_monitors(lowered, lines, 0, n, out);
    return out;
  }
  std::exception_ptr failure;
  std::thread second([&] {
    try {
      generate_monitors(lowered, lines, n / 2, n, out);
    } catch (...) {
      failure = std::current_exception();
    }
  });
  try {
    generate_monitors(lowered, lines, 0, n / 2, out);
  } catch (...) {
    second.join();
    throw;
  }
  second.join();
  if (failure) std::rethrow_exception(failure);
  return out;
}

}  // namespace

CodegenResult EmbeddedTarget::generate(const lower::LoweredApp& lowered) const {
  CodegenResult result;
  model::App app = lowered.app;  // gains the monitors' source maps and digests
  SpecLines lines(lowered.spec_text);
  std::vector<std::optional<GeneratedMonitor>> generated = generate_all_monitors(lowered, lines);
  std::vector<OutputFile> monitors;
  for (size_t i = 0; i < generated.size(); ++i) {
    if (!generated[i]) continue;
    GeneratedMonitor& g = *generated[i];
    model::Connection& c = app.connections[lowered.monitors[i].connection];
    // Every generated monitor must compile; if one does not, that is arbc's bug, and saying so
    // at build time beats a monitor failing on the robot.
    if (!g.compiles) {
      Diagnostic d;
      d.loc = c.loc;
      d.id = diag::Codegen.text();
      d.message = "internal error: the monitor generated for '" + c.name + "' is not valid Lua (" +
                  g.lua_error + "); please report this with the spec";
      result.diagnostics.push_back(std::move(d));
    }
    c.source_map = std::move(g.text.source_map);
    // Readers of the app directory refuse a monitor whose bytes differ (docs/app-json.md).
    c.monitor_sha256 = std::move(g.sha256);
    monitors.push_back({c.monitor, std::move(g.text.text)});
  }
  // The claims over delivered values the runtime checks on each delivery (claims_writer.h).
  if (std::optional<std::string> claims = write_claims(lowered)) {
    std::string lua_error;
    if (!frontend::LuaSyntaxChecker().check(*claims, kClaimsScript, &lua_error)) {
      Diagnostic d;
      d.id = diag::Codegen.text();
      d.message = "internal error: the claims script generated is not valid Lua (" + lua_error +
                  "); please report this with the spec";
      result.diagnostics.push_back(std::move(d));
    }
    app.claims_script = kClaimsScript;
    app.claims_script_sha256 = sha256_hex(*claims);
    monitors.push_back({kClaimsScript, std::move(*claims)});
  }
  result.files.push_back({"app.json", model::to_app_json(app)});
  for (OutputFile& f : monitors) result.files.push_back(std::move(f));
  result.ok = result.diagnostics.empty();
  return result;
}

}  // namespace arbc::codegen
