#include "compiler/codegen/embedded_target.h"

#include <gtest/gtest.h>

#include "compiler/codegen/monitor_writer.h"
#include "compiler/frontend/frontend.h"
#include "compiler/lower/compile_spec.h"
#include "core/sha256.h"

namespace arbc::codegen {
namespace {

// 100 ports of 12 rules with bodies: enough monitors that generation runs on two threads.
std::string many_monitors_spec() {
  std::string s = "app many_monitors;\nevent e0, e1, e2 lifetime 1s;\n";
  for (int k = 0; k < 12; ++k)
    s += "module Source" + std::to_string(k) + " { out value: float; }\n";
  for (int p = 0; p < 100; ++p) {
    std::string port = "Actuator" + std::to_string(p);
    s += "module " + port + " { in cmd: float; }\narbitrate " + port + ".cmd {\n";
    for (int k = 0; k < 12; ++k) {
      s += "  r" + std::to_string(k) + ": from Source" + std::to_string(k) + ".value when " +
           (k & 1 ? "e0" : "not e0") + " and " + (k & 2 ? "e1" : "not e1") + " { accept value > " +
           std::to_string(p) + ".5; emit value * " + std::to_string(k) + ".0; }\n";
    }
    s += "}\n";
  }
  return s;
}

TEST(EmbeddedTarget, ManyMonitorsComeOutInOrderWithTheirOwnTextAndDigest) {
  lower::CompiledSpec compiled = lower::compile_spec_text(many_monitors_spec(), "many.spec");
  ASSERT_TRUE(compiled.ok) << frontend::render_diagnostics(compiled.diagnostics, &compiled.sources);
  const lower::LoweredApp& lowered = *compiled.lowered;
  ASSERT_GE(lowered.monitors.size(), 1200u);

  CodegenResult r = EmbeddedTarget().generate(lowered);
  ASSERT_TRUE(r.ok);
  ASSERT_EQ(r.files.size(), lowered.monitors.size() + 1);
  ASSERT_EQ(r.files[0].path, "app.json");
  const std::string& app_json = r.files[0].content;

  // The reference: each monitor written on its own, in plan order.
  SpecLines lines(lowered.spec_text);
  for (size_t i = 0; i < lowered.monitors.size(); ++i) {
    const model::Connection& c = lowered.app.connections[lowered.monitors[i].connection];
    const OutputFile& f = r.files[i + 1];
    ASSERT_EQ(f.path, c.monitor) << i;
    EXPECT_EQ(f.content, write_monitor(lowered, lowered.monitors[i], lines).text) << f.path;
    EXPECT_NE(app_json.find("\"" + sha256_hex(f.content) + "\""), std::string::npos) << f.path;
  }
}

}  // namespace
}  // namespace arbc::codegen
