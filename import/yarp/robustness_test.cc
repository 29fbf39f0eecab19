// Hostile scripts and XML: the reader, the path analysis and the sandboxed run always return
// (a result or an error), never crash or hang (docs/reliability.md: bad input).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "import/yarp/lua_parser.h"
#include "import/yarp/script_facts.h"
#include "import/yarp/script_runner.h"
#include "import/yarp/yarp_evaluator.h"
#include "import/yarp/yarp_import.h"
#include "tests/support/tree_paths.h"

namespace arbc::yarp {
namespace {

std::vector<std::string> seed_scripts() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(arbc::testing::source_dir() +
                                                                     "/tests/yarp_verify")) {
    if (e.path().extension() != ".lua") continue;
    std::ifstream in(e.path());
    std::stringstream s;
    s << in.rdbuf();
    out.push_back(s.str());
  }
  return out;
}

std::string mutate(std::string text, std::mt19937& rng) {
  const std::string pieces[] = {
      "(",      ")",  "end",      "if",          "then",      "\"",     "[[",    "--[[",
      "\\",     "..", "function", "PortMonitor", "setEvent(", "goto x", "::x::", "while true do",
      "return", ",",  "{",        "}",           "="};
  int edits = 1 + static_cast<int>(rng() % 4);
  for (int i = 0; i < edits && !text.empty(); ++i) {
    size_t at = rng() % text.size();
    switch (rng() % 3) {
      case 0:
        text.erase(at, 1 + rng() % 8);
        break;
      case 1:
        text.insert(at, pieces[rng() % std::size(pieces)]);
        break;
      default:
        text[at] = static_cast<char>(rng() % 256);
    }
  }
  return text;
}

TEST(YarpImportRobustness, MutatedScriptsAlwaysGiveAnAnswer) {
  std::vector<std::string> seeds = seed_scripts();
  ASSERT_GT(seeds.size(), 20u);
  std::mt19937 rng(20261123);
  MonitorContext context{"m.lua", "/a", "/b", "tcp"};
  for (int round = 0; round < 400; ++round) {
    std::string text = mutate(seeds[rng() % seeds.size()], rng);
    SCOPED_TRACE("round " + std::to_string(round) + "\n" + text);
    std::string err;
    auto chunk = parse_lua(text, &err);
    if (chunk) {
      ScriptFacts f = analyse_script(*chunk);
      if (!f.paths_ok) {
        EXPECT_FALSE(f.paths_reason.empty());
      }
    } else {
      EXPECT_FALSE(err.empty());
    }
    ScriptRun run = run_script(text, "m.lua", context, sample_bottles({"a"}, {1}));
    if (!run.created) {
      EXPECT_FALSE(run.error.empty());
    }
  }
}

TEST(YarpImportRobustness, HostileConstraintsAreEvaluated) {
  auto ev = YarpEvaluator::create();
  for (const char* text : {"(((", "a and", "while true do end", "os.exit()", "e e e e e e",
                           "a b c d e f g h i j k l m", "\"", "]] --", "not not not"}) {
    ConstraintMeaning m = constraint_meaning(*ev, text);
    EXPECT_TRUE(m.parsed || !m.parse_error.empty()) << text;
  }
}

TEST(YarpImportRobustness, HostileXmlIsAnError) {
  std::string dir = ::testing::TempDir();
  for (const char* xml : {"", "<application>", "<a/>",
                          "<application><name>x</name>"
                          "<connection><from>/a</from></connection></application>",
                          "\xff\xfe<application/>"}) {
    std::string path = dir + "/hostile.xml";
    std::ofstream(path) << xml;
    YarpImport im = import_yarp(path, {});
    EXPECT_FALSE(im.ok) << xml;
    ASSERT_FALSE(im.diagnostics.empty()) << xml;
    EXPECT_EQ(im.diagnostics[0].id, kIdXml);
  }
}

}  // namespace
}  // namespace arbc::yarp
