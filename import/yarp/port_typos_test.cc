// yarp-port-name: a misspelt port is reported with the likely name; ports with close names
// that nothing links are left alone (tests/yarp_verify/port_spelling/ has the full output).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "import/yarp/yarp_import.h"

namespace arbc::yarp {
namespace {

using ::testing::HasSubstr;

// Writes an application of `connections` (from, to, monitor file or "") and its monitors into a
// fresh folder, and imports it.
class PortTypos : public ::testing::Test {
 protected:
  struct Link {
    std::string from, to, monitor;
  };

  void monitor(const std::string& name, const std::string& body) {
    std::ofstream(dir_ / (name + ".lua")) << "require(\"yarp\")\nPortMonitor.create = function(o)\n"
                                          << body << "\n  return true\nend\n";
  }

  YarpImport import(const std::vector<std::string>& modules, const std::vector<Link>& links) {
    std::ofstream xml(dir_ / "app.xml");
    xml << "<application>\n<name>app</name>\n";
    for (const std::string& m : modules) xml << "<module><name>" << m << "</name></module>\n";
    for (const Link& l : links) {
      xml << "<connection><from>" << l.from << "</from><to>" << l.to << "</to>";
      if (!l.monitor.empty())
        xml << "<protocol>tcp+recv.portmonitor+type.lua+file." << l.monitor << "</protocol>";
      xml << "</connection>\n";
    }
    xml << "</application>\n";
    xml.close();
    return import_yarp((dir_ / "app.xml").string(), {});
  }

  static std::vector<const Diagnostic*> typos(const YarpImport& im) {
    std::vector<const Diagnostic*> out;
    for (const Diagnostic& d : im.diagnostics)
      if (d.id == kIdPortName) out.push_back(&d);
    return out;
  }

  void SetUp() override {
    dir_ = std::filesystem::path(::testing::TempDir()) /
           ("port_typos_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    monitor("ball", "  PortMonitor.setConstraint(\"e_ball\")");
    monitor("line", "  PortMonitor.setConstraint(\"e_line\")");
    monitor("plain", "");
    std::ofstream(dir_ / "selector.lua")
        << "require(\"yarp\")\nPortMonitor.create = function(o) return true end\n"
           "PortMonitor.accept = function(t)\n  PortMonitor.setEvent(\"e_ball\")\n"
           "  PortMonitor.unsetEvent(\"e_line\")\n  return false\nend\n";
  }

  std::filesystem::path dir_;
};

TEST_F(PortTypos, ASelectorIntoAMisspeltPortNamesTheArbitratedOne) {
  YarpImport im = import({}, {{"/ball/out:o", "/ctrl/target:i", "ball"},
                              {"/line/out:o", "/ctrl/target:i", "line"},
                              {"/cmd/out:o", "/ctrl/traget:i", "selector"}});
  ASSERT_TRUE(im.ok);
  auto found = typos(im);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_THAT(found[0]->message, HasSubstr("did you mean /ctrl/target:i?"));
  EXPECT_EQ(found[0]->loc.line, 5);
}

TEST_F(PortTypos, AModuleMisspeltInAPortNameNamesTheModulesPort) {
  YarpImport im =
      import({"ball", "line", "cmd", "ctrl"}, {{"/bal/out:o", "/ctrl/target:i", "ball"},
                                               {"/line/out:o", "/ctrl/target:i", "line"},
                                               {"/cmd/out:o", "/ctrl/target:i", "selector"}});
  ASSERT_TRUE(im.ok);
  auto found = typos(im);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_THAT(found[0]->message, HasSubstr("did you mean /ball/out:o?"));
}

// Close names are common (/cam1, /cam2; /arm, /arm2): without events that link the ports, or a
// <module> left without a port, they are two ports.
TEST_F(PortTypos, CloseNamesThatNothingLinksAreTwoPorts) {
  YarpImport im =
      import({"ball", "line", "cam1", "cam2", "ctrl"}, {{"/ball/out:o", "/ctrl/target:i", "ball"},
                                                        {"/line/out:o", "/ctrl/target:i", "line"},
                                                        {"/ball/out:o", "/ctrl/target2:i", "plain"},
                                                        {"/cam1/img:o", "/ctrl/img1:i", ""},
                                                        {"/cam2/img:o", "/ctrl/img2:i", ""}});
  ASSERT_TRUE(im.ok);
  EXPECT_TRUE(typos(im).empty()) << typos(im)[0]->message;
}

}  // namespace
}  // namespace arbc::yarp
