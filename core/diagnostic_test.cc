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

TEST(Render, WithoutSourcesOrLocationPrintsTheMessageOnly) {
  Diagnostic d;
  d.message = "no such file";
  d.id = "io";
  d.loc.file = "missing.spec";
  EXPECT_EQ(render(d, nullptr), "missing.spec: error: no such file [io]\n");
}

}  // namespace
}  // namespace arbc
