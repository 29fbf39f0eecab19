#include "compiler/codegen/embedded_target.h"

#include "compiler/codegen/monitor_writer.h"
#include "compiler/frontend/lua_syntax.h"
#include "compiler/lower/lowered_app.h"
#include "core/app_json.h"
#include "core/sha256.h"

namespace arbc::codegen {

CodegenResult EmbeddedTarget::generate(const lower::LoweredApp& lowered) const {
  CodegenResult result;
  model::App app = lowered.app;  // gains the monitors' source maps and digests
  SpecLines lines(lowered.spec_text);
  std::vector<OutputFile> monitors;
  frontend::LuaSyntaxChecker lua;
  for (const lower::MonitorPlan& plan : lowered.monitors) {
    model::Connection& c = app.connections[plan.connection];
    if (c.monitor.empty()) continue;
    MonitorText m = write_monitor(lowered, plan, lines);
    // Every generated monitor must compile; if one does not, that is arbc's bug, and saying so
    // at build time beats a monitor failing on the robot.
    std::string error;
    if (!lua.check(m.text, c.monitor, &error)) {
      Diagnostic d;
      d.loc = c.loc;
      d.id = "codegen";
      d.message = "internal error: the monitor generated for '" + c.name + "' is not valid Lua (" +
                  error + "); please report this with the spec";
      result.diagnostics.push_back(std::move(d));
    }
    c.source_map = std::move(m.source_map);
    // Readers of the app directory refuse a monitor whose bytes differ (docs/app-json.md).
    c.monitor_sha256 = sha256_hex(m.text);
    monitors.push_back({c.monitor, std::move(m.text)});
  }
  result.files.push_back({"app.json", model::to_app_json(app)});
  for (OutputFile& f : monitors) result.files.push_back(std::move(f));
  result.ok = result.diagnostics.empty();
  return result;
}

}  // namespace arbc::codegen
