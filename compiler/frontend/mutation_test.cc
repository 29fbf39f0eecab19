// Property test in the spirit of a fuzzer (libFuzzer needs clang, and clang cannot compile the
// ANTLR 4.9 runtime headers as C++20): thousands of mutations of real specs, each of which
// must give a result whose diagnostics are well formed. A crash, hang or sanitizer report
// fails the test; the seed is fixed so a failure reproduces.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "compiler/frontend/frontend.h"
#include "core/check_ids.h"
#include "tests/support/tree_paths.h"

namespace arbc::frontend {
namespace {

std::vector<std::string> seed_specs() {
  std::vector<std::string> seeds;
  std::string root = arbc::testing::source_dir();
  for (const std::string& dir : {root + "/specs", root + "/tests/check"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
      if (entry.path().extension() != ".spec" || !entry.is_regular_file()) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream s;
      s << in.rdbuf();
      seeds.push_back(s.str());
    }
  }
  return seeds;
}

const char* const kTokens[] = {"app",   "module", "{",   "}",     "(",  ")",         ";",
                               ":",     ".",      "->",  "=>",    "in", "out",       "when",
                               "not",   "and",    "or",  "emit",  "if", "else",      "every",
                               "1s",    "0.5",    "\"",  "/*",    "*/", "otherwise", "hold",
                               "event", "x",      "e_a", "list<", ">",  "[",         "]"};

std::string mutate(std::string text, std::mt19937& rng) {
  int edits = 1 + static_cast<int>(rng() % 4);
  for (int i = 0; i < edits; ++i) {
    size_t at = text.empty() ? 0 : rng() % (text.size() + 1);
    switch (rng() % 5) {
      case 0:  // delete a range
        if (!text.empty() && at < text.size()) text.erase(at, 1 + rng() % 16);
        break;
      case 1:  // insert a token of the language
        text.insert(at, std::string(" ") + kTokens[rng() % std::size(kTokens)] + " ");
        break;
      case 2:  // duplicate a range
        if (!text.empty() && at < text.size()) text.insert(at, text.substr(at, 1 + rng() % 40));
        break;
      case 3:  // replace a byte with any byte (may break UTF-8)
        if (!text.empty() && at < text.size()) text[at] = static_cast<char>(rng());
        break;
      default:  // swap two ranges
        if (text.size() > 20) {
          size_t other = rng() % (text.size() - 10);
          std::string a = text.substr(other, 10);
          text.erase(other, 10);
          text.insert(std::min(at, text.size()), a);
        }
    }
  }
  return text;
}

TEST(Mutation, EveryMutatedSpecGivesWellFormedDiagnostics) {
  std::vector<std::string> seeds = seed_specs();
  ASSERT_GT(seeds.size(), 30u);
  std::set<std::string> ids;
  for (const CheckId& id : all_check_ids()) ids.insert(std::string(id.id));
  std::mt19937 rng(20261122);
  for (int round = 0; round < 3000; ++round) {
    std::string text = mutate(seeds[rng() % seeds.size()], rng);
    CheckResult r = check_text(text, "m.spec");
    SCOPED_TRACE("round " + std::to_string(round) + "\n" + text);
    if (!r.ok()) {
      ASSERT_FALSE(r.diagnostics.empty());
    }
    for (const Diagnostic& d : r.diagnostics) {
      ASSERT_TRUE(ids.count(d.id)) << "undeclared id [" << d.id << "]: " << d.message;
      ASSERT_FALSE(d.message.empty());
      ASSERT_EQ(d.message.find("T__"), std::string::npos) << d.message;  // no token dumps
      if (d.id != "empty-spec") {
        ASSERT_GE(d.loc.line, 1) << d.message;
        ASSERT_GE(d.loc.column, 1) << d.message;
      }
    }
    SourceCache sources;
    sources.add("m.spec", text);
    render_diagnostics(r.diagnostics, &sources);
  }
}

}  // namespace
}  // namespace arbc::frontend
