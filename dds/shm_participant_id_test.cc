// The participant id chosen clear of shared-memory segments left by earlier processes.
#include "dds/shm_participant_id.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace arbc::dds {
namespace {

namespace fs = std::filesystem;

class ShmParticipantIdTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("arbc-shm-id-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void leave_segment(uint32_t port) {
    std::ofstream(dir_ / ("fastrtps_port" + std::to_string(port)));
  }
  int choose(int domain, int limit = 100) {
    return participant_id_clear_of_segments(DdsPortPlan{}, domain, dir_.string(), limit);
  }
  fs::path dir_;
};

TEST_F(ShmParticipantIdTest, NoSegmentsGivesTheFirstId) { EXPECT_EQ(choose(0), 0); }

TEST_F(ShmParticipantIdTest, SkipsAnIdWhoseDiscoveryOrDataPortHasASegment) {
  // Domain 20: id 0 has ports 12410 and 12411, id 1 12412 and 12413, id 2 12414 and 12415.
  leave_segment(12410);  // id 0's discovery port, from a live or a dead process alike
  leave_segment(12413);  // id 1's data port only
  EXPECT_EQ(choose(20), 2);
}

TEST_F(ShmParticipantIdTest, ASegmentOfAnotherDomainDoesNotCount) {
  leave_segment(7410);  // domain 0, id 0
  leave_segment(7661);  // domain 1, id 0
  EXPECT_EQ(choose(2), 0);
}

TEST_F(ShmParticipantIdTest, FollowsTheProfilesPortArithmetic) {
  DdsPortPlan plan;
  plan.base = 20000;
  plan.domain_gain = 100;
  plan.participant_gain = 4;
  leave_segment(20000 + 100 * 3 + 10);  // id 0 under this plan
  EXPECT_EQ(participant_id_clear_of_segments(plan, 3, dir_.string()), 1);
}

TEST_F(ShmParticipantIdTest, EveryIdTakenLeavesTheChoiceToFastDds) {
  for (uint32_t port = 7410; port < 7420; ++port) leave_segment(port);
  EXPECT_EQ(choose(0, 5), -1);
}

TEST_F(ShmParticipantIdTest, StopsAtTheLastPort) {
  // Domain 232: id 0's data port is 65411; id 62's 65535; id 63's would be past it.
  for (int id = 0; id <= 62; ++id) leave_segment(65410 + 2 * id);
  EXPECT_EQ(choose(232), -1);
}

}  // namespace
}  // namespace arbc::dds
