// The keywords core keeps for the importers (core/spec_identifier.h) are the grammar's: a name
// an importer writes is never one the parser reads as a keyword (a YARP module called `test`
// or `resource` once became `module test`, which does not parse).
#include "compiler/frontend/grammar_info.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/spec_identifier.h"

namespace arbc::frontend {
namespace {

TEST(GrammarInfo, CoresKeywordListIsTheGrammarsSorted) {
  std::vector<std::string> core;
  for (std::string_view k : spec_keywords()) core.emplace_back(k);
  EXPECT_TRUE(std::is_sorted(core.begin(), core.end()));
  EXPECT_EQ(core, grammar_keywords());
}

TEST(GrammarInfo, AnIdentifierMadeFromAKeywordIsNotOne) {
  for (const std::string& k : grammar_keywords()) {
    std::string id = spec_identifier(k);
    EXPECT_NE(id, k);
    EXPECT_FALSE(is_spec_keyword(id)) << id;
  }
  EXPECT_EQ(spec_identifier("cmd-vel"), "cmd_vel");
  EXPECT_EQ(spec_identifier("2d"), "p_2d");
}

}  // namespace
}  // namespace arbc::frontend
