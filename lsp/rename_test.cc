// Rename (lsp/rename.cc) of modules and constants, and the tests files it reaches
// (lsp/tests_files.h), on files in a temporary folder; tests/lsp drives the same over stdio.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "lsp/analysis.h"
#include "lsp/features.h"
#include "lsp/tests_files.h"
#include "lsp/uri.h"

namespace arbc::lsp {
namespace {

namespace fs = std::filesystem;

const char* kApp = R"(app look "rename";
const LONG = 1s;
module Face { out face: vec3; }
module Scan { out gaze: vec3; }
module Head { in gaze: vec3; }
arbitrate Head.gaze by priority {
  track:  from Face.face hold LONG;
  search: from Scan.gaze;
}
)";

const char* kTests = R"(// tests of the app
tests for "%s";
test "looks around" {
  at LONG Scan.gaze <- vec3(1.0, 0.0, 0.0);
  expect Head.gaze receives at LONG;
}
)";

std::string tests_for(const std::string& app) {
  std::string text = kTests;
  return text.replace(text.find("%s"), 2, app);
}

class RenameFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() /
        ("arbc-rename-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "a" / "b" / "c");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& relative, const std::string& text) {
    fs::path p = dir_ / relative;
    std::ofstream(p) << text;
    return p.string();
  }

  Document document(const std::string& path, const std::string& text) {
    Document d;
    d.uri = path_to_uri(path);
    d.path = path;
    d.script_dir = fs::path(path).parent_path().string();
    d.text = text;
    d.analysis = analyze(text, 1, path, d.script_dir, nullptr);
    return d;
  }

  fs::path dir_;
};

TEST_F(RenameFiles, FindsTheAppsTestsFilesBesideItAndTwoFoldersBelow) {
  std::string app = write("app.spec", kApp);
  std::string beside = write("app.test.spec", tests_for("app.spec"));
  std::string below = write("a/b/more.test.spec", tests_for("../../app.spec"));
  write("a/b/c/too_deep.test.spec", tests_for("../../../app.spec"));
  write(".scratch.test.spec", tests_for("app.spec"));   // hidden: an editor's or a test's
  write("other.test.spec", tests_for("other.spec"));    // another app's
  write("a/not_a_spec.txt", tests_for("../app.spec"));  // not a .spec
  std::vector<std::string> found;
  for (const auto& [path, text] : tests_files_on_disk(app)) found.push_back(path);
  std::sort(found.begin(), found.end());
  EXPECT_EQ(found, (std::vector<std::string>{below, beside}));
}

TEST(TestsFiles, TheDeclarationMayFollowCommentsAndIsResolvedFromItsFolder) {
  EXPECT_TRUE(is_tests_file_of("/w/t/x.spec", "// a\n/* b */\n\ntests for \"../app.spec\";",
                               "/w/app.spec"));
  EXPECT_FALSE(is_tests_file_of("/w/t/x.spec", "tests for \"app.spec\";", "/w/app.spec"));
  EXPECT_FALSE(
      is_tests_file_of("/w/x.spec", "app x \"\"; // tests for \"app.spec\"", "/w/app.spec"));
}

TEST_F(RenameFiles, AConstantReachesTheTestsFilesGiven) {
  std::string app_path = write("app.spec", kApp);
  std::string tests_path = write("app.test.spec", tests_for("app.spec"));
  Document app = document(app_path, kApp), tests = document(tests_path, tests_for("app.spec"));
  ASSERT_TRUE(tests.analysis && tests.analysis->index);
  std::string err, warning;
  std::string text = kApp;
  Position at = lsp_position(text, 2, 7);  // const LONG
  auto edit = rename(app, at, "HOLD", {tests}, &err, &warning);
  ASSERT_TRUE(edit) << err;
  EXPECT_EQ((*edit)["changes"][app.uri].size(), 2u);    // the declaration and `hold LONG`
  EXPECT_EQ((*edit)["changes"][tests.uri].size(), 2u);  // `at LONG`, `receives at LONG`
  EXPECT_EQ(warning, "");
}

TEST_F(RenameFiles, AModuleIsRenamedInEveryModulePortWithAWarning) {
  std::string app_path = write("app.spec", kApp);
  std::string tests_path = write("app.test.spec", tests_for("app.spec"));
  Document app = document(app_path, kApp), tests = document(tests_path, tests_for("app.spec"));
  std::string err, warning;
  std::string text = kApp;
  auto edit = rename(app, lsp_position(text, 4, 8), "Looker", {tests}, &err, &warning);  // Scan
  ASSERT_TRUE(edit) << err;
  EXPECT_EQ((*edit)["changes"][app.uri].size(), 2u);  // `module Scan`, `from Scan.gaze`
  EXPECT_EQ((*edit)["changes"][tests.uri].size(), 1u);
  EXPECT_NE(warning.find("its plugin still registers it as 'Scan'"), std::string::npos) << warning;
  // A name another declaration has is refused, as for any rename.
  EXPECT_FALSE(rename(app, lsp_position(text, 4, 8), "Head", {}, &err, &warning));
  EXPECT_EQ(err, "there is already module 'Head'");
}

}  // namespace
}  // namespace arbc::lsp
