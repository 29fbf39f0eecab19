// Reading twist_mux's two forms, its bad input at the right line, and the rule each input gets.
#include <gtest/gtest.h>

#include "import/twist_mux/twist_mux_config.h"
#include "import/twist_mux/twist_mux_spec.h"

namespace arbc::twist_mux {
namespace {

MuxConfig read(const std::string& text) {
  MuxConfig c;
  read_twist_mux_text(text, "mux.yaml", c);
  return c;
}

TEST(TwistMuxConfig, TheRos2FormAndTheRos1FormReadAlike) {
  MuxConfig two = read(
      "twist_mux:\n  ros__parameters:\n    topics:\n      nav:\n        topic: nav_vel\n"
      "        timeout: 0.5\n        priority: 10\n    locks:\n      stop:\n"
      "        topic: e_stop\n        timeout: 0.0\n        priority: 255\n");
  MuxConfig one = read(
      "topics:\n- name: nav\n  topic: nav_vel\n  timeout: 0.5\n  priority: 10\n"
      "locks:\n- name: stop\n  topic: e_stop\n  timeout: 0.0\n  priority: 255\n");
  for (const MuxConfig* c : {&two, &one}) {
    ASSERT_TRUE(c->diagnostics.empty()) << c->diagnostics[0].message;
    ASSERT_EQ(c->inputs.size(), 1u);
    ASSERT_EQ(c->locks.size(), 1u);
    EXPECT_EQ(c->inputs[0].name, "nav");
    EXPECT_EQ(c->inputs[0].topic, "nav_vel");
    EXPECT_EQ(c->inputs[0].timeout, 0.5);
    EXPECT_EQ(c->locks[0].priority, 255);
    EXPECT_TRUE(c->locks[0].lock);
  }
  EXPECT_EQ(two.inputs[0].loc.line, 4);
  EXPECT_EQ(one.inputs[0].loc.line, 2);
}

TEST(TwistMuxConfig, BadInputIsAnErrorAtItsLine) {
  MuxConfig c = read("topics:\n- name: nav\n  topic: nav_vel\n  timeout: soon\n  priority: 10\n");
  ASSERT_EQ(c.diagnostics.size(), 1u);
  EXPECT_EQ(c.diagnostics[0].severity, Severity::Error);
  EXPECT_EQ(c.diagnostics[0].loc.line, 4);
  EXPECT_NE(c.diagnostics[0].message.find("`timeout:`, a number"), std::string::npos);
  c = read("cmd_vel: [1, 2\n");
  ASSERT_EQ(c.diagnostics.size(), 1u);
  EXPECT_NE(c.diagnostics[0].message.find("not YAML"), std::string::npos);
  c = read("other_node:\n  ros__parameters:\n    rate: 10\n");
  EXPECT_TRUE(c.inputs.empty());
  c = read("hello: world\n");
  ASSERT_EQ(c.diagnostics.size(), 1u);
  EXPECT_NE(c.diagnostics[0].message.find("not a twist_mux parameter file"), std::string::npos);
}

TEST(TwistMuxConfig, APriorityOutsideTheRangeIsClampedAsTwistMuxDoes) {
  MuxConfig c = read("topics:\n- name: nav\n  topic: nav_vel\n  timeout: 0.5\n  priority: 300\n");
  ASSERT_EQ(c.inputs.size(), 1u);
  EXPECT_EQ(c.inputs[0].priority, 255);
  ASSERT_EQ(c.diagnostics.size(), 1u);
  EXPECT_EQ(c.diagnostics[0].severity, Severity::Warning);
  EXPECT_EQ(c.diagnostics[0].loc.line, 5);
}

TEST(TwistMuxSpec, AnInputIsKeptOutByActiveInputsAndEngagedLocksAboveIt) {
  MuxConfig c = read(
      "topics:\n- name: nav\n  topic: nav_vel\n  timeout: 0.5\n  priority: 10\n"
      "- name: joy\n  topic: joy_vel\n  timeout: 0.5\n  priority: 100\n"
      "locks:\n- name: stop\n  topic: e_stop\n  timeout: 0.2\n  priority: 50\n");
  MuxSpec s = write_mux_spec(c, "mux.yaml", "cmd_vel_out");
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_NE(s.spec.find("  joy: from Joy.cmd_vel\n      when joy_active {\n"), std::string::npos)
      << s.spec;
  EXPECT_NE(
      s.spec.find("  nav: from Nav.cmd_vel\n      when nav_active\n       and not joy_active\n"
                  "       and not stop_lock {\n"),
      std::string::npos)
      << s.spec;
  EXPECT_NE(s.spec.find("event stop_lock = lock StopLock.lock timeout 200ms;"), std::string::npos)
      << s.spec;
  EXPECT_NE(s.deploy.find("\"Base.cmd_vel\": \"/cmd_vel_out\""), std::string::npos) << s.deploy;
}

TEST(TwistMuxSpec, ATieIsAWarningAtTheSecondPriority) {
  MuxConfig c = read(
      "topics:\n- name: a\n  topic: a\n  timeout: 0.5\n  priority: 100\n"
      "- name: b\n  topic: b\n  timeout: 0.5\n  priority: 100\n");
  MuxSpec s = write_mux_spec(c, "mux.yaml", "cmd_vel_out");
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0].loc.line, 9);
  EXPECT_NE(s.warnings[0].message.find("same priority, 100"), std::string::npos);
}

}  // namespace
}  // namespace arbc::twist_mux
