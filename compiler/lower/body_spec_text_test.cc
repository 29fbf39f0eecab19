// core/body_spec_text.h against the real parser: an assert over `emitted` written back in spec
// syntax and compiled again as an assert of the same spec lowers to the same IR, for a spec
// made to stress precedence and literals and for every such assert in the repository's specs.
#include "core/body_spec_text.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler/lower/lower_test_util.h"
#include "core/body_text.h"
#include "tests/support/tree_paths.h"

namespace arbc::lower {
namespace {

// The spec with each of its asserts over `emitted` stated again from its printed text: the
// number of asserts compared; a failure for each that does not read back as the same IR.
int assert_again(const std::string& text, const std::string& where) {
  CompiledSpec first = compile_spec_text(text, "test.spec", ".");
  if (!first.ok) return 0;
  std::string again = text;
  std::vector<std::string> ir;  // what each assert lowered to, in the order appended
  for (const model::ArbitratedPort& p : first.lowered->app.arbitrated_ports)
    for (const model::Assertion& a : p.asserts) {
      if (!a.emitted) continue;
      std::string printed = model::body_expr_spec_text(*a.emitted, "emitted");
      again += "\nassert " + p.port + ": " + a.rule + " -> " + printed + ";\n";
      ir.push_back(model::body_expr_text(*a.emitted));
    }
  if (ir.empty()) return 0;
  CompiledSpec second = compile_spec_text(again, "test.spec", ".");
  EXPECT_TRUE(second.ok) << where << ":\n" << again;
  if (!second.ok) return 0;
  std::vector<std::string> read;
  for (const model::ArbitratedPort& p : second.lowered->app.arbitrated_ports)
    for (const model::Assertion& a : p.asserts)
      if (a.emitted) read.push_back(model::body_expr_text(*a.emitted));
  // The spec's own asserts come first in each port, then the ones appended; compare as sets of
  // texts counted twice.
  for (const std::string& s : ir)
    EXPECT_EQ(std::count(read.begin(), read.end(), s), 2 * std::count(ir.begin(), ir.end(), s))
        << where << ": " << s;
  return static_cast<int>(ir.size());
}

TEST(BodySpecText, PrecedenceLiteralsAndCallsReadBackAsTheSameIr) {
  const char* spec = R"(app printed;
module Src { out m: {x: float, n: int, xs: list<{d: float, id: int}>, s: string, v: vec3}; }
module Dst { in m: {x: float, n: int, xs: list<{d: float, id: int}>, s: string, v: vec3}; }
const K = 3;
arbitrate Dst.m { r: from Src.m; }
assert Dst.m: r -> emitted.x - (1.0 - 2.5) * -emitted.x > 0.1;
assert Dst.m: r -> not (emitted.n % K == 1 or emitted.n / 2 < 7) and emitted.x != 3.0;
assert Dst.m: r -> emitted.x > emitted.n and emitted.x <= 1e-300 + 0.30000000000000004;
assert Dst.m: r -> len(emitted.xs) == 0 or min_by(emitted.xs, e => e.d - 1.0).id >= 0;
assert Dst.m: r -> emitted.s == "a \"b\"\n" and emitted.v.x - emitted.xs[0].d < K;
)";
  EXPECT_EQ(assert_again(spec, "made"), 5);
}

TEST(BodySpecText, EveryAssertOverEmittedInTheRepositoryReadsBackAsTheSameIr) {
  namespace fs = std::filesystem;
  int asserts = 0;
  for (const char* dir : {"specs", "examples", "tests"}) {
    for (const auto& entry :
         fs::recursive_directory_iterator(arbc::testing::source_dir() + "/" + dir)) {
      if (!entry.is_regular_file() || entry.path().extension() != ".spec") continue;
      std::ifstream in(entry.path());
      std::stringstream text;
      text << in.rdbuf();
      if (text.str().find("emitted") == std::string::npos) continue;
      asserts += assert_again(text.str(), entry.path().string());
    }
  }
  EXPECT_GE(asserts, 10);  // the walk found the repository's asserts over data
}

}  // namespace
}  // namespace arbc::lower
