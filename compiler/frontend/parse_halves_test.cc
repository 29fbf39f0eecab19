// The two-thread parse of a large spec (parse_halves.h) gives what the one-thread parse gives:
// the same AST, the same diagnostics in the same order, also when it has to give up.
#include "compiler/frontend/parse_halves.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "compiler/frontend/parse.h"
#include "compiler/frontend/text_stream.h"

namespace arbc::frontend {
namespace {

constexpr size_t kOneThread = SIZE_MAX;
constexpr size_t kTwoThreads = 0;

// A spec of `ports` arbitrated ports with `rules` rules each, with bodies, non-ASCII text (so
// that code point and byte offsets differ) and comments in both halves.
std::string make_spec(int ports, int rules) {
  std::string s = "app big \"Großer Test\";\n/* a comment\n   over lines */\nconst T = 0.5;\n";
  for (int p = 0; p < ports; ++p) {
    std::string n = std::to_string(p);
    s += "module Src" + n + " \"Kamera " + n + " ✓\" { out value: float; }\n";
    s += "module Act" + n + " { in cmd: float; }\n";
    s += "event e" + n + "_0, e" + n + "_1 lifetime 1s;\n";
  }
  for (int p = 0; p < ports; ++p) {
    std::string n = std::to_string(p);
    s += "// port " + n + ", ünïcode\narbitrate Act" + n + ".cmd {\n";
    for (int r = 0; r < rules; ++r) {
      std::string c = r % 2 ? "e" + n + "_0 and not e" + n + "_1" : "not e" + n + "_0";
      s += "  r" + n + "_" + std::to_string(r) + ": from Src" + n + ".value when " + c + " {\n";
      s += "    let x = value * 2.0;\n    if x > T { emit x; } else { emit -T; }\n  }\n";
    }
    s += "}\n";
  }
  return s;
}

std::string where(const ast::Loc& l) {
  return l.file.str() + ":" + std::to_string(l.line) + ":" + std::to_string(l.column) + "-" +
         std::to_string(l.end_line) + ":" + std::to_string(l.end_column);
}

void print(const ast::Expr* e, std::string& out) {
  if (!e) {
    out += "-";
    return;
  }
  out += "(" + std::to_string(static_cast<int>(e->kind)) + " " + where(e->loc) + " " + e->text +
         " " + std::string(e->op) + " " + std::to_string(e->number);
  for (const auto& n : e->names) out += " " + n.name + "@" + where(n.loc);
  for (const auto& a : e->args) print(a.get(), out);
  out += ")";
}

void print(const ast::Block& block, std::string& out) {
  for (const auto& s : block) {
    out += "[" + std::to_string(static_cast<int>(s->kind)) + " " + where(s->loc) + " " + s->name +
           " " + where(s->name_loc) + " " + s->text;
    print(s->expr.get(), out);
    if (s->duration) print(s->duration->expr.get(), out);
    print(s->body, out);
    out += s->has_else ? " else " : " ";
    print(s->else_body, out);
    out += "]";
  }
}

// The parts of the AST these specs have, as text.
std::string describe(const ParseResult& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics) out += render(d, nullptr);
  if (!r.spec) return out + "no spec\n";
  const ast::Spec& s = *r.spec;
  out += s.file + (s.app ? " app " + s.app->name + " " + s.app->doc + " " + where(s.app->loc) : "");
  out += "\nconsts";
  for (const auto& c : s.consts) {
    out += " " + c.name + where(c.loc);
    print(c.value.get(), out);
  }
  out += "\nmodules";
  for (const auto& m : s.modules) {
    out += " " + m.name + " " + m.doc + where(m.loc);
    for (const auto& p : m.ports) out += " " + p.name + where(p.loc) + p.type.name;
  }
  out += "\nevents";
  for (const auto& e : s.events)
    for (const auto& n : e.names) out += " " + n.name + where(n.loc);
  for (const auto& a : s.arbitrations) {
    out += "\narbitrate " + a.port.qualified() + where(a.loc);
    for (const auto& rule : a.rules) {
      out += "\n  " + rule.name + where(rule.loc) + " " + rule.source.qualified() +
             where(rule.source.loc);
      print(rule.when.get(), out);
      print(rule.body, out);
    }
  }
  return out + "\n";
}

// The one-thread parse, and the two-thread one, which must not have given up when `halves`.
void expect_same_parse(const std::string& text, bool halves) {
  ParseResult one = parse_spec(text, "big.spec", kOneThread);
  ParseResult two = parse_spec(text, "big.spec", kTwoThreads);
  EXPECT_EQ(describe(one), describe(two));
  std::optional<size_t> split = find_split(text);
  ASSERT_TRUE(split);
  EXPECT_EQ(parse_halves(text, decode_utf8(text), "big.spec", *split).has_value(), halves);
}

TEST(ParseHalves, SplitsAtALineThatStartsADeclarationAfterTheMiddle) {
  std::string text = "app a;\nmodule M { in x: float; }\n  module\nmodules\narbitrate M.x {}\n";
  std::optional<size_t> split = find_split(text);
  ASSERT_TRUE(split);
  EXPECT_EQ(text.substr(*split), "arbitrate M.x {}\n");
  EXPECT_FALSE(find_split("app a;\nmodule M { in x: float; }\n"));
}

TEST(ParseHalves, GivesTheSameAstAsOneThread) {
  std::string text = make_spec(8, 12);
  ParseResult two = parse_spec(text, "big.spec", kTwoThreads);
  ASSERT_TRUE(two.spec);
  EXPECT_TRUE(two.diagnostics.empty());
  EXPECT_EQ(two.spec->arbitrations.size(), 8u);
  expect_same_parse(text, true);
}

TEST(ParseHalves, AboveTheThresholdParseSpecUsesTwoThreadsWithTheSameResult) {
  std::string text = make_spec(60, 40);
  ASSERT_GE(text.size(), kTwoThreadParseBytes);
  EXPECT_EQ(describe(parse_spec(text, "big.spec")),
            describe(parse_spec(text, "big.spec", kOneThread)));
  expect_same_parse(text, true);
}

TEST(ParseHalves, KeepsTheBuildersDiagnosticsOfBothHalvesInOrder) {
  std::string text = make_spec(8, 12);
  text.replace(text.find("\"Kamera 1 "), 1, "\"\\q");
  text.replace(text.rfind("\"Kamera 7 "), 1, "\"\\w");
  ParseResult two = parse_spec(text, "big.spec", kTwoThreads);
  ASSERT_EQ(two.diagnostics.size(), 2u);
  EXPECT_EQ(two.diagnostics[0].id, "bad-escape");
  expect_same_parse(text, true);
}

TEST(ParseHalves, ASyntaxErrorInTheSecondHalfGivesTheOneThreadDiagnostics) {
  std::string text = make_spec(8, 12);
  text.replace(text.rfind("when not e7_0"), 4, "wen");
  ParseResult two = parse_spec(text, "big.spec", kTwoThreads);
  EXPECT_FALSE(two.spec);
  ASSERT_FALSE(two.diagnostics.empty());
  expect_same_parse(text, false);
}

TEST(ParseHalves, ASyntaxErrorInTheFirstHalfGivesTheOneThreadDiagnostics) {
  std::string text = make_spec(8, 12);
  text.replace(text.find("arbitrate Act0.cmd {"), 20, "arbitrate Act0.cmd");
  expect_same_parse(text, false);
}

TEST(ParseHalves, ALexicalErrorGivesTheOneThreadDiagnostics) {
  std::string text = make_spec(8, 12);
  text.replace(text.rfind("value * 2.0"), 11, "value * 2x0 $");
  expect_same_parse(text, false);
}

TEST(ParseHalves, ACommentAcrossTheCutIsNotCut) {
  std::string text = make_spec(8, 12);
  size_t split = *find_split(text);
  text.insert(split, "/* commented out:\n");
  text.insert(*find_split(text) + 100, "*/");  // closes it inside the next declaration
  expect_same_parse(text, false);
}

TEST(ParseHalves, TwoAppsOneInEachHalfGiveTheOneThreadDiagnostic) {
  std::string text = make_spec(8, 12);
  text.insert(*find_split(text), "app second;\n");
  ParseResult two = parse_spec(text, "big.spec", kTwoThreads);
  ASSERT_EQ(two.diagnostics.size(), 1u);
  EXPECT_EQ(two.diagnostics[0].id, "duplicate");
  expect_same_parse(text, false);
}

}  // namespace
}  // namespace arbc::frontend
