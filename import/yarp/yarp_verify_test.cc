// import/yarp/yarp_verify.h: a yarpmanager application proved like a spec, its counterexamples
// pointed at the Lua lines that set the rules' constraints.
#include "import/yarp/yarp_verify.h"

#include <gtest/gtest.h>

#include "tests/support/tree_paths.h"

namespace arbc::yarp {
namespace {

std::string fixture(const std::string& name) {
  return arbc::testing::source_dir() + "/tests/yarp_verify/" + name + "/" + name + ".xml";
}

TEST(YarpVerifyTest, AnApplicationWithOverlappingRulesIsRefutedWithTheLuaLines) {
  YarpVerify y = verify_yarp_application(fixture("always_selected"), verify::VerifyOptions{}, {});
  ASSERT_TRUE(y.ok) << y.diagnostics;
  EXPECT_EQ(y.report.verdict, verify::Verdict::Refuted);
  bool noted = false;
  for (const verify::PortResult& p : y.report.ports) {
    for (const verify::Finding& f : p.findings) {
      if (f.check != verify::kCheckExclusive) continue;
      for (const verify::Note& n : f.notes)
        noted |=
            n.message.find("sets its constraint `e_ball or not e_ball` here") != std::string::npos;
    }
  }
  EXPECT_TRUE(noted);
}

TEST(YarpVerifyTest, AMalformedApplicationIsBadInput) {
  YarpVerify y = verify_yarp_application(fixture("xml_malformed"), verify::VerifyOptions{}, {});
  EXPECT_FALSE(y.ok);
  EXPECT_NE(y.diagnostics.find("error:"), std::string::npos) << y.diagnostics;
  EXPECT_TRUE(is_yarp_application("apps/x.xml"));
  EXPECT_FALSE(is_yarp_application("apps/x.spec"));
}

}  // namespace
}  // namespace arbc::yarp
