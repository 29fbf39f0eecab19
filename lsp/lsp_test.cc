// Unit tests of the language server's pieces; the whole server is tested over stdio by
// tests/lsp (protocol suite, Neovim).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <mutex>
#include <sstream>
#include <thread>

#include "compiler/frontend/frontend.h"
#include "compiler/frontend/grammar_info.h"
#include "lsp/debounced_worker.h"
#include "lsp/framing.h"
#include "lsp/lsp_diagnostics.h"
#include "lsp/positions.h"
#include "lsp/symbol_index.h"
#include "lsp/text_edits.h"
#include "lsp/uri.h"

namespace arbc::lsp {
namespace {

TEST(Framing, ReadsMessagesAndSkipsBrokenHeaders) {
  std::istringstream in(
      "Content-Length: 2\r\n\r\n{}"
      "X-Other: 1\r\n\r\n"
      "content-length: 3\r\nContent-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n[1]"
      "Content-Length: 10\r\n\r\n{}");
  std::string err;
  EXPECT_EQ(read_message(in, &err), "{}");
  EXPECT_EQ(err, "");
  EXPECT_EQ(read_message(in, &err), "");  // no Content-Length: skipped, said
  EXPECT_NE(err.find("Content-Length"), std::string::npos);
  err.clear();
  EXPECT_EQ(read_message(in, &err), "[1]");
  EXPECT_EQ(read_message(in, &err), std::nullopt);  // the body is cut short
  EXPECT_EQ(err, "the input ended inside a message body");
}

TEST(Framing, SkipsAnOversizedMessageAndGoesOn) {
  std::string big = "Content-Length: " + std::to_string(kMaxMessageBytes + 1) + "\r\n\r\n";
  std::istringstream in(big + std::string(kMaxMessageBytes + 1, ' ') +
                        "Content-Length: 2\r\n\r\n{}");
  std::string err;
  EXPECT_EQ(read_message(in, &err), "");
  EXPECT_NE(err.find("larger than"), std::string::npos);
  err.clear();
  EXPECT_EQ(read_message(in, &err), "{}");
}

TEST(Framing, WritesContentLength) {
  std::ostringstream out;
  MessageWriter(out).write("{\"a\":1}");
  EXPECT_EQ(out.str(), "Content-Length: 7\r\n\r\n{\"a\":1}");
}

TEST(Positions, CountUtf16UnitsAgainstCodePoints) {
  std::string text = "ab\né😀x\n";                    // é: 1 unit, 😀: 2 units, 1 code point each
  EXPECT_EQ(lsp_position(text, 2, 3).character, 3);  // before x
  EXPECT_EQ(offset_of(text, {1, 3}), text.find('x'));
  EXPECT_EQ(arbc_position(text, {1, 3}), std::make_pair(2, 3));
  EXPECT_EQ(offset_of(text, {1, 99}), text.find('x') + 1);  // past the end of the line
  EXPECT_EQ(offset_of(text, {9, 0}), text.size());          // past the last line
}

TEST(Positions, ClampOutOfRangeNumbersFromTheClient) {
  std::string text = "ab\ncd";
  Position p = parse_position({{"line", 1e15}, {"character", -7}});  // 1e15: a float, ignored
  EXPECT_EQ(p.line, 0);
  p = parse_position({{"line", int64_t{1} << 40}, {"character", -7}});
  EXPECT_EQ(p.line, std::numeric_limits<int>::max() - 1);
  EXPECT_EQ(p.character, 0);
  EXPECT_EQ(offset_of(text, p), text.size());
  EXPECT_EQ(arbc_position(text, p).first, std::numeric_limits<int>::max());
  EXPECT_EQ(parse_position({{"line", uint64_t{1} << 63}}).line,
            std::numeric_limits<int>::max() - 1);
  EXPECT_EQ(parse_position("x").line, 0);
}

TEST(TextEdits, AppliesRangesAndWholeText) {
  std::string text = "line one\nline two\n";
  std::string err;
  nlohmann::json change = {
      {"range",
       {{"start", {{"line", 1}, {"character", 5}}}, {"end", {{"line", 1}, {"character", 8}}}}},
      {"text", "2"}};
  ASSERT_TRUE(apply_change(text, change, &err));
  EXPECT_EQ(text, "line one\nline 2\n");
  ASSERT_TRUE(apply_change(text, {{"text", "new"}}, &err));
  EXPECT_EQ(text, "new");
  EXPECT_FALSE(apply_change(text, {{"range", 5}, {"text", "x"}}, &err));
  EXPECT_FALSE(apply_change(text, {{"nothing", 1}}, &err));
  EXPECT_EQ(text, "new");
}

TEST(Uri, RoundTripsPathsWithSpacesAndPercent) {
  EXPECT_EQ(uri_to_path(path_to_uri("/tmp/a b/100%.spec")), "/tmp/a b/100%.spec");
  EXPECT_EQ(path_to_uri("/tmp/a b.spec"), "file:///tmp/a%20b.spec");
  EXPECT_EQ(uri_to_path("untitled:Untitled-1"), "untitled:Untitled-1");
  EXPECT_EQ(uri_to_path("file://host/x%2"), "/x%2");
}

TEST(Diagnostics, DidYouMeanIsAFix) {
  frontend::CheckResult r = frontend::check_text(
      "app a \"x\";\nmodule M { in p: int; out q: int; }\nevent e_taken;\n"
      "arbitrate M.p { r: from M.q when e_tkn; }\n",
      "/x.spec", ".");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(suggested_fix(r.diagnostics[0]), "e_taken");
  nlohmann::json j = diagnostic_json(r.diagnostics[0], r.source, "file:///x.spec");
  EXPECT_EQ(j["code"], "unknown-event");
  EXPECT_EQ(j["data"]["fix"], "e_taken");
  EXPECT_EQ(j["range"]["start"]["line"], 3);
}

// A tests file shows an error in its app's spec at its own start, saying where, with the
// place as related information and no fix (the name to replace is not in this document).
TEST(Diagnostics, AnotherFilesErrorIsAtTheStartWithItsPlace) {
  frontend::CheckResult r = frontend::check_text(
      "app a \"x\";\nmodule M { in p: int; out q: int; }\nevent e_taken;\n"
      "arbitrate M.p { r: from M.q when e_tkn; }\n",
      "/app.spec", ".");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  nlohmann::json j =
      diagnostic_json(r.diagnostics[0], "tests for \"app.spec\";\n", "file:///app.test.spec");
  EXPECT_EQ(j["message"], "/app.spec:4:34: unknown event 'e_tkn'");
  EXPECT_EQ(j["range"]["start"]["line"], 0);
  EXPECT_FALSE(j.contains("data"));
  ASSERT_GE(j["relatedInformation"].size(), 2u);
  EXPECT_EQ(j["relatedInformation"][0]["location"]["uri"], "file:///app.spec");
  EXPECT_EQ(j["relatedInformation"][0]["location"]["range"]["start"]["line"], 3);
  EXPECT_EQ(j["relatedInformation"][0]["location"]["range"]["start"]["character"], 33);
  // The "did you mean" note has no place of its own: it points at the diagnostic as shown.
  EXPECT_EQ(j["relatedInformation"][1]["location"]["uri"], "file:///app.test.spec");
  EXPECT_EQ(j["relatedInformation"][1]["message"], "did you mean 'e_taken'?");
}

TEST(SymbolIndex, ResolvesUsesToDeclarations) {
  frontend::CheckResult r = frontend::check_text(
      "app a \"x\";\nmodule M { in p: int; out q: int; }\nevent e;\n"
      "arbitrate M.p { r: from M.q when not e { let v = q + 1; accept v > 0; set e; } }\n",
      "x.spec", ".");
  ASSERT_TRUE(r.ok()) << frontend::render_diagnostics(r.diagnostics, nullptr);
  std::unique_ptr<SymbolIndex> ix = build_index(*r.spec);
  const Occurrence* o = ix->occurrence_at(4, 38);  // the `e` of `not e`
  ASSERT_NE(o, nullptr);
  EXPECT_EQ(ix->symbols[o->symbol].key, "event:e");
  EXPECT_EQ(ix->occurrences_of(o->symbol).size(), 3u);  // declared, when, set
  EXPECT_EQ(ix->set_by.at("e"), std::vector<std::string>{"r"});
  const Occurrence* v = ix->occurrence_at(4, 64);  // the `v` of `accept v`
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(ix->symbols[v->symbol].kind, SymbolKind::Local);
  EXPECT_EQ(ix->symbols[v->symbol].def.column, 46);
}

// A constant where a duration goes is a use of it (find references, rename), in properties
// over time and assumptions as much as in rules.
TEST(SymbolIndex, ConstantsInDurationsAreUses) {
  frontend::CheckResult r = frontend::check_text(
      "app a \"x\";\nconst D = 1s;\nmodule M { in p: int; out q: int; out s: int; }\n"
      "event e = M.s: s > 0;\n"
      "arbitrate M.p { r: from M.q when not e { accept q > 0; } t: from M.s when e { accept true; "
      "} "
      "}\n"
      "never two r within D;\ngiven M.q every D;\nstable M.p for D;\nassume not e for D after r;\n",
      "x.spec", ".");
  ASSERT_TRUE(r.ok()) << frontend::render_diagnostics(r.diagnostics, nullptr);
  std::unique_ptr<SymbolIndex> ix = build_index(*r.spec);
  const Occurrence* decl = ix->occurrence_at(2, 7);
  ASSERT_NE(decl, nullptr);
  ASSERT_EQ(ix->symbols[decl->symbol].key, "const:D");
  std::vector<int> lines;
  for (const Occurrence* o : ix->occurrences_of(decl->symbol)) lines.push_back(o->loc.line);
  std::sort(lines.begin(), lines.end());
  EXPECT_EQ(lines, (std::vector<int>{2, 6, 7, 8, 9}));
}

// A test's `expect exclusive M.p;` uses the port, and `expect assert M.p: RULE -> EXPR;` the
// port, the rule and the events, as a declared assert does (find references, rename).
TEST(SymbolIndex, ClaimExpectationsAreUses) {
  frontend::CheckResult r = frontend::check_text(
      "app a \"x\";\nmodule M { in p: int; out q: int; out s: int; }\nevent e, f;\n"
      "arbitrate M.p { r: from M.q when e; t: from M.s when not e; }\n"
      "test \"claims\" {\n  at 0s M.q <- 1;\n  expect exclusive M.p;\n"
      "  expect assert M.p: r -> f;\n}\n",
      "x.spec", ".");
  ASSERT_TRUE(r.ok()) << frontend::render_diagnostics(r.diagnostics, nullptr);
  std::unique_ptr<SymbolIndex> ix = build_index(*r.spec);
  const Occurrence* port = ix->occurrence_at(7, 22);  // the `p` of `expect exclusive M.p`
  ASSERT_NE(port, nullptr);
  EXPECT_EQ(ix->symbols[port->symbol].key.substr(0, 5), "port:");
  const Occurrence* rule = ix->occurrence_at(8, 22);  // the `r` of `expect assert M.p: r`
  ASSERT_NE(rule, nullptr);
  EXPECT_EQ(ix->occurrences_of(rule->symbol).size(), 2u);  // declared, asserted
  const Occurrence* event = ix->occurrence_at(8, 27);      // the `f` of `-> f`
  ASSERT_NE(event, nullptr);
  EXPECT_EQ(ix->symbols[event->symbol].key, "event:f");
}

TEST(GrammarInfo, KeywordsComeFromTheGrammar) {
  std::vector<std::string> k = frontend::grammar_keywords();
  for (const char* word : {"arbitrate", "when", "module", "otherwise"})
    EXPECT_NE(std::find(k.begin(), k.end(), word), k.end()) << word;
  EXPECT_EQ(std::find(k.begin(), k.end(), "{"), k.end());
  // The cache can be dropped between parses, and parsing still works.
  frontend::reset_parser_cache();
  EXPECT_TRUE(frontend::check_text("app a \"x\";\nmodule M { in p: int; }\n", "x.spec", ".").ok());
}

TEST(DebouncedWorker, RunsOnceForABurstOfSchedules) {
  std::atomic<int> runs{0};
  {
    DebouncedWorker w(std::chrono::milliseconds(200), [&](const std::string&) { ++runs; });
    for (int i = 0; i < 20; ++i) w.schedule("doc");
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  }
  EXPECT_EQ(runs, 1);
}

// A document closed while its analysis waits: the worker must not read the cancelled entry
// (ASan caught it reading the deadline of the freed node when it woke up), and what is still
// scheduled runs.
TEST(DebouncedWorker, ACancelWhileTheWorkerWaitsLeavesTheRestToRun) {
  std::atomic<int> runs{0};
  std::string last;
  std::mutex mutex;
  {
    DebouncedWorker w(std::chrono::milliseconds(200), [&](const std::string& key) {
      std::lock_guard lock(mutex);
      last = key;
      ++runs;
    });
    w.schedule("closed");
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the worker waits on it
    w.cancel("closed");
    w.schedule("open");
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
  }
  EXPECT_EQ(runs, 1);
  EXPECT_EQ(last, "open");
}

}  // namespace
}  // namespace arbc::lsp
