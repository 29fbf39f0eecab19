#include "import/yarp/spec_names.h"

#include <gtest/gtest.h>

#include <array>

namespace arbc::yarp {
namespace {

// An import of connections FROM -> TO (each on its own line of a.xml) with rule names: only
// what the naming reads.
YarpImport app(const std::vector<std::array<std::string, 3>>& connections) {
  YarpImport im;
  int line = 1;
  for (const auto& [from, to, name] : connections) {
    ImportedConnection ic;
    ic.xml.id = name;
    ic.xml.from = from;
    ic.xml.to = to;
    ic.xml.loc = ic.xml.id_loc = ic.xml.from_loc = ic.xml.to_loc = {"a.xml", line++, 1, 0, 0};
    im.connections.push_back(ic);
    model::Connection c;
    c.name = name;
    c.source = from;
    c.destination = to;
    im.app.connections.push_back(c);
  }
  return im;
}

std::string qualified(const std::map<std::string, SpecPort>& ports, const std::string& yarp) {
  return ports.at(yarp).module + "." + ports.at(yarp).port;
}

// Merged, two YARP modules would be one spec module: the later is told apart, and said so at
// its port, with a note at the other.
TEST(SpecNames, TwoModulesThatBecomeOneNameStayTwo) {
  std::vector<Diagnostic> said;
  auto ports = spec_port_names(app({{"/a-b/x", "/c/in", "r"}, {"/a_b/y", "/c/in", "s"}}), said);
  EXPECT_EQ(qualified(ports, "/a-b/x"), "a_b.x");
  EXPECT_EQ(qualified(ports, "/a_b/y"), "a_b_2.y");
  EXPECT_EQ(qualified(ports, "/c/in"), "c.in_");
  ASSERT_EQ(said.size(), 1u);
  EXPECT_EQ(said[0].id, "yarp-spec-name");
  EXPECT_EQ(said[0].severity, Severity::Warning);
  EXPECT_EQ(said[0].loc.line, 2);
  EXPECT_EQ(said[0].message,
            "YARP module '/a_b' (of port /a_b/y) becomes the spec module 'a_b', as does '/a-b' of "
            "the port at line 1: in the imported spec this module is 'a_b_2'");
  EXPECT_EQ(said[0].notes[0].loc.line, 1);
}

// The same YARP module is one spec module, whether its name is a port's whole name or a
// prefix; and a same-named port in two modules is no collision.
TEST(SpecNames, OneYarpModuleIsOneSpecModule) {
  std::vector<Diagnostic> said;
  auto ports = spec_port_names(app({{"/x", "/m/in", "r"}, {"/x/y", "/n/in", "s"}}), said);
  EXPECT_EQ(qualified(ports, "/x"), "x.port");
  EXPECT_EQ(qualified(ports, "/x/y"), "x.y");
  EXPECT_EQ(qualified(ports, "/m/in"), "m.in_");
  EXPECT_EQ(qualified(ports, "/n/in"), "n.in_");
  EXPECT_TRUE(said.empty());
}

// A name told apart skips the names others have as they are: `/a_b_2` keeps `a_b_2`, even
// when it comes last.
TEST(SpecNames, ANameTakenAsItIsIsNeverGivenToAnother) {
  std::vector<Diagnostic> said;
  auto ports = spec_port_names(
      app({{"/a-b/x", "/c/in", "r"}, {"/a_b/y", "/c/in", "s"}, {"/a_b_2/z", "/c/in", "t"}}), said);
  EXPECT_EQ(ports.at("/a_b/y").module, "a_b_3");
  EXPECT_EQ(ports.at("/a_b_2/z").module, "a_b_2");
  EXPECT_EQ(said.size(), 1u);
  std::vector<Diagnostic> rules_said;
  std::vector<std::string> rules = spec_rule_names(
      app({{"/a/o", "/c/in", "x-y"}, {"/b/o", "/c/in", "x_y"}, {"/d/o", "/c/in", "x_y_2"}}),
      rules_said);
  EXPECT_EQ(rules, (std::vector<std::string>{"x_y", "x_y_3", "x_y_2"}));
  ASSERT_EQ(rules_said.size(), 1u);
  EXPECT_EQ(rules_said[0].id, "yarp-spec-name");
}

// Two ports of one module whose names become one spec name.
TEST(SpecNames, TwoPortsOfAModuleThatBecomeOneNameStayTwo) {
  std::vector<Diagnostic> said;
  auto ports = spec_port_names(app({{"/m/p:o", "/c/in", "r"}, {"/m/p-o", "/c/in", "s"}}), said);
  EXPECT_EQ(qualified(ports, "/m/p:o"), "m.p_o");
  EXPECT_EQ(qualified(ports, "/m/p-o"), "m.p_o_2");
  ASSERT_EQ(said.size(), 1u);
  EXPECT_EQ(said[0].message,
            "YARP port /m/p-o becomes the spec port 'm.p_o', as does /m/p:o at line 1: in the "
            "imported spec it is 'm.p_o_2'");
}

}  // namespace
}  // namespace arbc::yarp
