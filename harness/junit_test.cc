// harness/junit.h: the JUnit XML of a run, escaped, with a headline per failure.
#include "harness/junit.h"

#include <gtest/gtest.h>

namespace arbc::harness {
namespace {

TEST(JunitTest, SuitesCountTheirTestsAndFailures) {
  TestOutcome pass{"a <b>", true, "", 0.25, ""};
  TestOutcome fail{"c", false,
                   "  t.spec:3:3: expected X at 1s\n  but nothing reached X at 1s\n  trace:\n", 1,
                   ""};
  std::string xml = junit_xml({{"specs/t.spec", "app", {pass, fail}}});
  EXPECT_NE(xml.find("<testsuite name=\"specs/t.spec\" tests=\"2\" failures=\"1\" errors=\"0\" "
                     "time=\"1.250\">"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<testcase name=\"a &lt;b&gt;\" classname=\"app\" time=\"0.250\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<failure message=\"t.spec:3:3: expected X at 1s; but nothing reached X at "
                     "1s\">"),
            std::string::npos)
      << xml;
}

TEST(JunitTest, AnAbsoluteSpecPathIsNamedAsArtifactsNameIt) {
  TestOutcome fail{"c", false, "  /nowhere-arbc/x/t.spec:3:3: expected X\n", 0, ""};
  std::string xml = junit_xml({{"/nowhere-arbc/x/t.spec", "app", {fail}}});
  EXPECT_EQ(xml.find("/nowhere-arbc"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<testsuite name=\"t.spec\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("t.spec:3:3: expected X"), std::string::npos) << xml;
}

}  // namespace
}  // namespace arbc::harness
