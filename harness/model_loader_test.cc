// harness/model_loader.h: one door for a spec, an app.json or a built directory; each failure
// said for the user and kept as a diagnostic for the JSON and SARIF reports.
#include "harness/model_loader.h"

#include <fstream>

#include "harness/harness_test_util.h"

namespace arbc::harness {
namespace {

std::string source(const std::string& rel) { return arbc::testing::source_dir() + "/" + rel; }

TEST(ModelLoaderTest, ReadsAnAppJsonItsDirectoryAndASpecAlike) {
  LoadNotes notes;
  std::string err;
  std::optional<model::App> from_json =
      load_model(source("tests/verify/table_clean.app.json"), &notes, &err);
  ASSERT_TRUE(from_json) << err;
  std::optional<model::App> from_spec = load_model(source("specs/table_clean.spec"), &notes, &err);
  ASSERT_TRUE(from_spec) << err;
  EXPECT_EQ(from_json->name, "table_clean");
  EXPECT_EQ(from_spec->arbitrated_ports.size(), from_json->arbitrated_ports.size());
  std::string dir = testing::scratch();
  std::ifstream in(source("tests/verify/table_clean.app.json"));
  std::ofstream(dir + "/app.json") << in.rdbuf();
  EXPECT_TRUE(load_model(dir, &notes, &err)) << err;
}

TEST(ModelLoaderTest, EachFailureIsSaidAndKept) {
  LoadNotes missing;
  std::string err;
  EXPECT_FALSE(load_model("no/such/app.json", &missing, &err));
  EXPECT_EQ(err,
            "no/such/app.json: cannot read the file; give a spec (*.spec), an app.json, or a "
            "directory written by `arbc build`");
  ASSERT_EQ(missing.errors.size(), 1u);
  EXPECT_EQ(missing.errors[0].id, "io");

  LoadNotes malformed;
  EXPECT_FALSE(load_model(source("tests/verify/malformed.app.json"), &malformed, &err));
  EXPECT_NE(err.find("not a valid app.json"), std::string::npos) << err;
  EXPECT_NE(malformed.rendered.find("error:"), std::string::npos) << malformed.rendered;

  LoadNotes bad_spec;
  EXPECT_FALSE(load_model(source("tests/verify/bad.spec"), &bad_spec, &err));
  EXPECT_NE(err.find("not verified: the spec has errors"), std::string::npos) << err;
  EXPECT_FALSE(bad_spec.errors.empty());
}

TEST(ModelLoaderTest, AYarpBuildIsNamedForWhatItIs) {
  std::string dir = testing::scratch();
  std::ofstream(dir + "/ports.json") << "{}";
  LoadNotes notes;
  std::string err;
  EXPECT_FALSE(load_model(dir, &notes, &err));
  EXPECT_NE(err.find("a build for YARP"), std::string::npos) << err;
}

}  // namespace
}  // namespace arbc::harness
