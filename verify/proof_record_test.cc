// verify/proof_record.h: a recorded proof is trusted only for the very app.json it names, by
// the very binary that wrote it.
#include "verify/proof_record.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/tree_paths.h"
#include "verify/executable_id.h"

namespace arbc::verify {
namespace {

// One folder per test: ctest runs the tests of this file in parallel processes, and a shared
// folder was removed by one while the other wrote into it.
std::string scratch() {
  std::string dir = arbc::testing::binary_dir() + "/proof_record_test_scratch/" +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(ProofRecordTest, ARecordIsTrustedForItsAppJsonOnly) {
  if (executable_build_id().empty()) GTEST_SKIP() << "this binary has no build id";
  const std::string app_json = "{\"schema_version\": 2}\n";
  std::string record = proof_record(app_json, "verified: 4 arbitrated ports proved exclusive");
  ASSERT_FALSE(record.empty());
  std::string dir = scratch();
  EXPECT_EQ(recorded_proof(dir, app_json), std::nullopt);  // no record yet
  std::ofstream(dir + "/" + kProofRecordFile) << record;
  EXPECT_EQ(recorded_proof(dir, app_json), "verified: 4 arbitrated ports proved exclusive");
  EXPECT_EQ(recorded_proof(dir, app_json + " "), std::nullopt);  // another app.json
  std::ofstream(dir + "/" + kProofRecordFile) << "not json";
  EXPECT_EQ(recorded_proof(dir, app_json), std::nullopt);
}

TEST(ProofRecordTest, ARecordOfAnotherBinaryIsNotTrusted) {
  if (executable_build_id().empty()) GTEST_SKIP() << "this binary has no build id";
  const std::string app_json = "{}";
  std::string record = proof_record(app_json, "verified");
  std::string id = executable_build_id();
  size_t at = record.find(id);
  ASSERT_NE(at, std::string::npos);
  record[at] = record[at] == '0' ? '1' : '0';
  std::string dir = scratch();
  std::ofstream(dir + "/" + kProofRecordFile) << record;
  EXPECT_EQ(recorded_proof(dir, app_json), std::nullopt);
}

}  // namespace
}  // namespace arbc::verify
