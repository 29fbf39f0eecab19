#include "import/yarp/xml_mismatch.h"

#include <gtest/gtest.h>

namespace arbc::yarp {
namespace {

TEST(XmlMismatch, PointsAtTheClosingTagWithTheTypo) {
  std::optional<XmlMismatch> m = find_xml_mismatch(
      "<application>\n  <name>x</name>\n  <connection>\n    <from>/a</from>\n"
      "  </connectoin>\n</application>\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->line, 5);
  EXPECT_EQ(m->column, 3);
  EXPECT_EQ(m->found, "</connectoin>");
  EXPECT_EQ(m->open, "<connection>");
  EXPECT_EQ(m->open_line, 3);
}

TEST(XmlMismatch, SkipsCommentsDeclarationsAndSelfClosingTags) {
  EXPECT_FALSE(find_xml_mismatch(
      "<?xml version=\"1.0\"?>\n<!DOCTYPE a>\n<a><!-- </b> -->\n<c x=\"1\"/><![CDATA[</d>]]></a>"));
}

TEST(XmlMismatch, AnElementNeverClosed) {
  std::optional<XmlMismatch> m = find_xml_mismatch("<application>\n  <module>\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->found, "");
  EXPECT_EQ(m->open, "<module>");
  EXPECT_EQ(m->line, 2);
}

TEST(XmlMismatch, AClosingTagWithNothingOpen) {
  std::optional<XmlMismatch> m = find_xml_mismatch("<a></a>\n</b>");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->found, "</b>");
  EXPECT_EQ(m->open, "");
  EXPECT_EQ(m->line, 2);
}

}  // namespace
}  // namespace arbc::yarp
