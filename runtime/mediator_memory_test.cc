#include "runtime/mediator_memory.h"

#include <gtest/gtest.h>

#include <string>

namespace arbc {
namespace {

SavedMemory sample() {
  SavedMemory m;
  m.file = "memory.json";
  m.time = Nanos(5'000'000'000);
  m.wall_ns = 1'000'000'000'000;
  m.entries = {{"Arm.cmd", "e_open", "feed_Arm_cmd", kNever},
               {"Arm.cmd", "e_busy", "feed_Arm_cmd", Nanos(6'000'000'000)}};
  m.last_delivery = {{"take", Nanos(4'900'000'000)}};
  return m;
}

// What is written is read back as it was, "until unset" included.
TEST(MediatorMemoryTest, ReadsBackWhatItWrites) {
  nlohmann::json checks = {{"properties", nlohmann::json::array()}};
  nlohmann::json doc = memory_json("grip", 42, sample(), checks);
  SavedMemory back;
  back.file = "memory.json";
  nlohmann::json checks_back;
  std::string error;
  ASSERT_TRUE(parse_memory(doc, "grip", 42, &back, &checks_back, &error)) << error;
  EXPECT_EQ(back.time, sample().time);
  EXPECT_EQ(back.wall_ns, sample().wall_ns);
  ASSERT_EQ(back.entries.size(), 2u);
  EXPECT_EQ(back.entries[0].expiry, kNever);
  EXPECT_EQ(back.entries[1].event, "e_busy");
  EXPECT_EQ(back.entries[1].expiry, Nanos(6'000'000'000));
  ASSERT_EQ(back.last_delivery.size(), 1u);
  EXPECT_EQ(back.last_delivery[0].second, Nanos(4'900'000'000));
  EXPECT_EQ(checks_back, checks);
}

// Another app, another build of it (its fingerprint), a wrong shape: refused, saying what to do.
TEST(MediatorMemoryTest, RefusesAnotherAppABuildOrAShape) {
  nlohmann::json doc = memory_json("grip", 42, sample(), nlohmann::json::object());
  std::string error;
  SavedMemory m;
  m.file = "memory.json";
  nlohmann::json checks;
  EXPECT_FALSE(parse_memory(doc, "grip", 43, &m, &checks, &error));
  EXPECT_NE(error.find("another build of app 'grip'"), std::string::npos) << error;
  EXPECT_FALSE(parse_memory(doc, "other", 42, &m, &checks, &error));
  doc["entries"][0].erase("owner");
  EXPECT_FALSE(parse_memory(doc, "grip", 42, &m, &checks, &error));
  EXPECT_NE(error.find("remove it to start this mediator with no memory"), std::string::npos)
      << error;
  EXPECT_FALSE(parse_memory(nlohmann::json::array(), "grip", 42, &m, &checks, &error));
}

// The saved instants move by the wall time since the write, times the time scale; a clock set
// back moves them by nothing rather than backwards.
TEST(MediatorMemoryTest, ShiftsByTheWallTimePassed) {
  SavedMemory m = sample();
  int64_t two_s_later = m.wall_ns + 2'000'000'000;
  // A new run started at its 1 s: the saved 5 s instant maps to 1 s - 2 s passed.
  EXPECT_EQ(m.time + memory_shift(m, Nanos(1'000'000'000), two_s_later, 1.0),
            Nanos(1'000'000'000 - 2'000'000'000));
  EXPECT_EQ(m.time + memory_shift(m, Nanos(1'000'000'000), two_s_later, 10.0),
            Nanos(1'000'000'000 - 20'000'000'000));
  EXPECT_EQ(m.time + memory_shift(m, Nanos(1'000'000'000), m.wall_ns - 5'000'000'000, 1.0),
            Nanos(1'000'000'000));
}

}  // namespace
}  // namespace arbc
