#include "core/script_lines.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

TEST(ScriptLines, MarkersAreFoundWithTheLinesTheyAnnounce) {
  std::string monitor = "-- generated\nlocal x = 1\n  " + script_begin_line("specs/track.lua", 3) +
                        "\nline1\nline2\nline3\n-- ---- end\n";
  std::vector<ScriptSpan> spans = script_spans(monitor);
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].first, 4);
  EXPECT_EQ(spans[0].lines, 3);
  EXPECT_EQ(spans[0].file, "specs/track.lua");
  // A file name with spaces and parentheses survives.
  spans = script_spans(script_begin_line("my (old) script.lua", 1) + "\nx\n");
  ASSERT_EQ(spans.size(), 1u);
  EXPECT_EQ(spans[0].file, "my (old) script.lua");
  // A line that only looks like a marker is not one.
  EXPECT_TRUE(
      script_spans("-- ---- begin x (y lines; run-time errors in them cite that file)\n").empty());
}

TEST(ScriptLines, ErrorsInsideTheScriptCiteTheUsersFile) {
  std::vector<ScriptSpan> spans = {{10, 5, "specs/track.lua"}};
  const char* chunk = "monitors/HeadControl.gaze__track.lua";
  EXPECT_EQ(
      cite_script_lines("monitors/HeadControl.gaze__track.lua:12: attempt to index a nil value",
                        chunk, spans),
      "specs/track.lua:3: attempt to index a nil value");
  // Lines outside the script keep citing the monitor; every occurrence is rewritten.
  EXPECT_EQ(cite_script_lines("monitors/HeadControl.gaze__track.lua:40: bad argument "
                              "(called from monitors/HeadControl.gaze__track.lua:14:)",
                              chunk, spans),
            "monitors/HeadControl.gaze__track.lua:40: bad argument (called from "
            "specs/track.lua:5:)");
  EXPECT_EQ(cite_script_lines("monitors/HeadControl.gaze__track.lua:15: x", chunk, spans),
            "monitors/HeadControl.gaze__track.lua:15: x");
  EXPECT_EQ(cite_script_lines("no position", chunk, spans), "no position");
}

}  // namespace
}  // namespace arbc
