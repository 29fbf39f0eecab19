#include "core/diagnostic.h"

#include <gtest/gtest.h>

namespace arbc {
namespace {

Diagnostic at(int line, int column, int end_column, std::string message) {
  Diagnostic d;
  d.loc.file = "x.spec";
  d.loc.line = d.loc.end_line = line;
  d.loc.column = column;
  d.loc.end_column = end_column;
  d.message = std::move(message);
  d.id = "unknown-event";
  return d;
}

TEST(Render, QuotesTheLineWithACaretAndNotes) {
  SourceCache sources;
  sources.add("x.spec", "app t;\n  take: from A.b when not e_tken;\n");
  Diagnostic d = at(2, 27, 33, "unknown event 'e_tken'");
  Diagnostic note;
  note.severity = Severity::Note;
  note.message = "did you mean 'e_taken'?";
  d.notes.push_back(note);
  EXPECT_EQ(render(d, &sources),
            "x.spec:2:27: error: unknown event 'e_tken' [unknown-event]\n"
            "    take: from A.b when not e_tken;\n"
            "                            ^~~~~~\n"
            "note: did you mean 'e_taken'?\n");
}

TEST(Render, CountsColumnsInCharactersAndKeepsTabs) {
  SourceCache sources;
  sources.add("x.spec", "\t\"\xC3\xA9t\xC3\xA9\" bad\n");
  EXPECT_EQ(render(at(1, 8, 11, "m"), &sources),
            "x.spec:1:8: error: m [unknown-event]\n"
            "  \t\"\xC3\xA9t\xC3\xA9\" bad\n"
            "  \t      ^~~\n");
}

TEST(Render, ShowsControlCharactersEscapedAndKeepsTheCaretUnderTheColumn) {
  SourceCache sources;
  sources.add("x.spec", "a \x1b[31m b\x7f c;\n");
  // Column 12 is the 'c' (the escape sequence counts 5 characters, DEL one); each escaped
  // character takes 4 columns on screen.
  EXPECT_EQ(render(at(1, 12, 13, "unknown name 'c'\x1b[0m"), &sources),
            "x.spec:1:12: error: unknown name 'c'\\x1B[0m [unknown-event]\n"
            "  a \\x1B[31m b\\x7F c;\n"
            "  " +
                std::string(17, ' ') + "^\n");
}

TEST(Render, CutsALongLineToAboutTwoHundredColumnsAroundTheCaret) {
  SourceCache sources;
  std::string line = std::string(1000, 'a') + " bad " + std::string(1000, 'b');
  sources.add("x.spec", line + "\n");
  std::string text = render(at(1, 1002, 1005, "m"), &sources);
  size_t quote = text.find('\n') + 1;
  std::string quoted = text.substr(quote, text.find('\n', quote) - quote);
  std::string caret = text.substr(text.find('\n', quote) + 1);
  // 100 columns left of the caret (99 a's and the space), 200 in all.
  EXPECT_EQ(quoted, "  ..." + std::string(99, 'a') + " bad " + std::string(96, 'b') + "...");
  EXPECT_EQ(caret, std::string(5 + 100, ' ') + "^~~\n");
  // A short line is shown whole; a cut at the start only when the caret is far from it.
  std::string start = render(at(1, 3, 4, "m"), &sources);
  EXPECT_NE(start.find("\n  aaa"), std::string::npos);
  EXPECT_NE(start.find(std::string(198, 'a') + "...\n  " + "  ^\n"), std::string::npos);
}

TEST(Render, WithoutSourcesOrLocationPrintsTheMessageOnly) {
  Diagnostic d;
  d.message = "no such file";
  d.id = "io";
  d.loc.file = "missing.spec";
  EXPECT_EQ(render(d, nullptr), "missing.spec: error: no such file [io]\n");
}

}  // namespace
}  // namespace arbc
