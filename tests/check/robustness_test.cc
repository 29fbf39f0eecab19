// `arbc check` on hostile input: every case ends with a diagnostic and exit 2 (or 0 where the
// input is valid), never a signal, a hang or an uncaught exception. Runs the real binary.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "tests/support/tree_paths.h"

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int exit_code = -1;
  std::string output;
};

class CheckRobustness : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("arbc_robustness_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) {
    fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }

  // Runs `arbc check ARGS`, with a time limit so a hang fails instead of blocking the suite.
  Outcome check(const std::string& args) {
    fs::path out = dir_ / "output.txt";
    std::string command = "timeout 60 " + arbc::testing::binary_dir() + "/cli/arbc check " + args +
                          " > " + out.string() + " 2>&1";
    int status = std::system(command.c_str());
    Outcome r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(out);
    std::stringstream buffer;
    buffer << in.rdbuf();
    r.output = buffer.str();
    return r;
  }

  fs::path dir_;
};

TEST_F(CheckRobustness, EmptyFile) {
  Outcome r = check(write("empty.spec", ""));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("the spec is empty"), std::string::npos) << r.output;
}

TEST_F(CheckRobustness, RandomBytes) {
  std::mt19937 rng(12345);
  for (int i = 0; i < 20; ++i) {
    std::string bytes(1 + rng() % 8192, '\0');
    for (char& c : bytes) c = static_cast<char>(rng());
    Outcome r = check(write("random.spec", bytes));
    EXPECT_EQ(r.exit_code, 2) << "seed round " << i << ": " << r.output;
    EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
  }
}

TEST_F(CheckRobustness, RandomAsciiTokens) {
  // Valid UTF-8 built from the language's own vocabulary: exercises the parser's recovery.
  const char* words[] = {"app", "module", "{",  "}",     "(",     ")",         ";",    ":",
                         ".",   "->",     "=>", "in",    "out",   "arbitrate", "when", "not",
                         "and", "x",      "1s", "\"s\"", "emit",  "if",        "else", "[",
                         "]",   ",",      "=",  "+",     "event", "otherwise", "0.5"};
  std::mt19937 rng(7);
  for (int i = 0; i < 30; ++i) {
    std::string text;
    for (int k = 0; k < 300; ++k) text += std::string(words[rng() % std::size(words)]) + " ";
    Outcome r = check(write("tokens.spec", text));
    EXPECT_EQ(r.exit_code, 2) << text;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
  }
}

TEST_F(CheckRobustness, NotUtf8) {
  Outcome r = check(write("latin1.spec", "app t \"caf\xE9\";\n"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("not valid UTF-8"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("latin1.spec:1:11:"), std::string::npos) << r.output;
}

TEST_F(CheckRobustness, TenThousandNestedParentheses) {
  std::string spec =
      "app t;\nconst C = " + std::string(10000, '(') + "1" + std::string(10000, ')') + ";\n";
  Outcome r = check(write("deep.spec", spec));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("nesting is deeper than 100 levels"), std::string::npos) << r.output;
}

TEST_F(CheckRobustness, LongOperatorAndPrefixChains) {
  std::string nots = "app t;\nconst C = ";
  for (int i = 0; i < 10000; ++i) nots += "not ";
  Outcome r = check(write("nots.spec", nots + "true;\n"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("[nesting-too-deep]"), std::string::npos) << r.output;

  std::string sum = "app t;\nconst C = 1";
  for (int i = 0; i < 100000; ++i) sum += " + 1";
  r = check(write("sum.spec", sum + ";\n"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("[nesting-too-deep]"), std::string::npos) << r.output;
}

TEST_F(CheckRobustness, TenThousandElseIfs) {
  std::string spec =
      "app t;\nmodule A { out x: float; }\nmodule B { in y: float; }\n"
      "connect A.x -> B.y {\n  if x > 0.0 { emit x; }";
  for (int i = 0; i < 10000; ++i) spec += " else if x > 1.0 { emit x; }";
  spec += "\n}\n";
  Outcome r = check(write("elseif.spec", spec));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("[nesting-too-deep]"), std::string::npos) << r.output;
}

TEST_F(CheckRobustness, TenMegabyteSpecIsValid) {
  std::string spec = "app big;\nmodule S { out v: float; }\n";
  int ports = 0;
  while (spec.size() < 10u << 20) {
    spec += "module A" + std::to_string(ports) + " { in c: float; }\narbitrate A" +
            std::to_string(ports) + ".c {\n";
    for (int k = 0; k < 100; ++k)
      spec +=
          "  r" + std::to_string(k) + ": from S.v when false { accept v > 0.5; emit v * 2.0; }\n";
    spec += "}\n";
    ++ports;
  }
  Outcome r = check(write("big.spec", spec));
  EXPECT_EQ(r.exit_code, 0) << r.output.substr(0, 2000);
  EXPECT_EQ(r.output, "");
}

TEST_F(CheckRobustness, DirectoryMissingAndUnreadable) {
  Outcome r = check(dir_.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("is a directory"), std::string::npos) << r.output;

  r = check((dir_ / "missing.spec").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("no such file"), std::string::npos) << r.output;

  std::string locked = write("locked.spec", "app t;\n");
  fs::permissions(locked, fs::perms::none);
  r = check(locked);
  if (std::ifstream(locked).good()) {
    EXPECT_EQ(r.exit_code, 0) << r.output;  // running as root: permissions do not stop reads
  } else {
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("cannot open"), std::string::npos) << r.output;
  }
}

TEST_F(CheckRobustness, SeveralFilesReportEachAndFailIfAnyFails) {
  std::string good = arbc::testing::source_dir() + "/specs/table_clean.spec";
  std::string bad = write("bad.spec", "app t;\nmodule A { out x: flot; }\n");
  Outcome r = check(good + " " + bad);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("bad.spec:2:19: error: unknown type 'flot'"), std::string::npos)
      << r.output;
  r = check(good);
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST_F(CheckRobustness, UsageErrorsAndHelp) {
  EXPECT_EQ(check("").exit_code, 2);
  EXPECT_EQ(check("--format xml x.spec").exit_code, 2);
  Outcome help = check("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--format"), std::string::npos);
}

TEST_F(CheckRobustness, JsonFormat) {
  std::string bad = write("bad.spec", "app t;\nmodule A { out x: flot; }\n");
  Outcome r = check("--format json " + bad + " 2>/dev/null");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("\"id\": \"unknown-type\""), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\"line\": 2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("did you mean 'float'?"), std::string::npos) << r.output;
}

}  // namespace
