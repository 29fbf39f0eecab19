#include "examples/table_clean/world.h"

#include <gtest/gtest.h>

#include <cmath>

namespace arbc::table_clean {
namespace {

TEST(World, TheObjectDetectorListsOnlyObjectsOnTheTableWithBoundedNoise) {
  World world(3);
  const int a = world.add_object(table_point(0.30, 0.0));
  const int b = world.add_object(table_point(0.60, 0.4));
  const int c = world.add_object(table_point(0.85, -0.4));
  world.object(a).place = Place::Hand;
  world.object(b).place = Place::Bucket;
  for (int i = 0; i < 200; ++i) {
    const auto seen = world.detect_objects(0.1 * i);
    ASSERT_EQ(seen.size(), 1u);
    const double err = (seen[0].pos - world.object(c).pos).norm();
    EXPECT_LE(err, kDetectorNoise * std::sqrt(3.0));
    EXPECT_GT(err, 0.0);
    EXPECT_NEAR(seen[0].dist, seen[0].pos.norm(), 1e-12);
    EXPECT_EQ(zone_of(seen[0].dist), Zone::Beyond);
  }
}

TEST(World, TheSameSeedGivesTheSameDetections) {
  World w1(42), w2(42), w3(43);
  for (World* w : {&w1, &w2, &w3}) w->add_object(table_point(0.5, 0.1));
  EXPECT_EQ(w1.detect_objects(0)[0].pos, w2.detect_objects(0)[0].pos);
  EXPECT_NE(w1.detect_objects(0.1)[0].pos, w3.detect_objects(0.1)[0].pos);
}

TEST(World, TheFaceIsSeenOnlyWhileTheHeadLooksAtThePerson) {
  World world(4);
  EXPECT_FALSE(world.detect_face(0.0));  // initial gaze: at the table
  world.head().look_at(world.person().face(), 0.0);
  EXPECT_FALSE(world.detect_face(0.05));  // still turning
  const auto seen = world.detect_face(2.0);
  ASSERT_TRUE(seen);
  EXPECT_GE(seen->certainty, 0.8);
  EXPECT_LE((seen->pos - world.person().face()).norm(), kDetectorNoise * std::sqrt(3.0));
  world.person().set_present(false);
  EXPECT_FALSE(world.detect_face(2.1));
  world.person().set_present(true);
  world.head().look_at(Vec3(1.0, -1.0, 0.3), 2.2);
  EXPECT_FALSE(world.detect_face(4.0));
}

TEST(World, TheHeadTurnsAtBoundedSpeed) {
  World world(5);
  Head& head = world.head();
  const Vec3 start = head.gaze_direction(0.0);
  head.look_at(head.position() + Vec3(0.0, 1.0, 0.0), 0.0);
  const double total = angle_between(start, Vec3(0, 1, 0));
  EXPECT_NEAR(angle_between(start, head.gaze_direction(0.1)), Head::kSpeed * 0.1, 1e-9);
  EXPECT_NEAR(angle_between(head.gaze_direction(total / Head::kSpeed), Vec3(0, 1, 0)), 0, 1e-7);
}

TEST(World, APersonWhoHearsARequestMovesTheNearestUnreachableObjectAfterAFewSeconds) {
  World world(6);
  const int far = world.add_object(table_point(0.90, 0.1));
  const int nearer = world.add_object(table_point(0.80, -0.3));
  const int tool = world.add_object(table_point(0.60, 0.0));
  world.person().hear("Please put the object closer!", 10.0);
  world.person().hear("Please put the object closer!", 10.5);  // already on it
  world.advance_to(10.0 + Person::kMinHelpDelay - 0.01);
  EXPECT_EQ(world.person().objects_moved(), 0);
  world.advance_to(10.0 + Person::kMaxHelpDelay);
  EXPECT_EQ(world.person().objects_moved(), 1);
  EXPECT_EQ(world.person().requests_heard(), 2);
  EXPECT_EQ(zone_of(distance_from_robot(world.object(nearer).pos)), Zone::Hand);
  EXPECT_EQ(zone_of(distance_from_robot(world.object(far).pos)), Zone::Beyond);
  EXPECT_EQ(zone_of(distance_from_robot(world.object(tool).pos)), Zone::Tool);
}

TEST(World, AnAbsentPersonDoesNotHelp) {
  World world(7);
  world.add_object(table_point(0.90, 0.1));
  world.person().set_present(false);
  world.person().hear("Please put the object closer!", 0.0);
  world.advance_to(100.0);
  EXPECT_EQ(world.person().objects_moved(), 0);
}

TEST(World, TheAgendaRunsInTimeOrderAndTellsItsListener) {
  World world(8);
  std::vector<double> listened, ran;
  world.set_agenda_listener([&](double at) { listened.push_back(at); });
  world.schedule(2.0, [&] { ran.push_back(world.now()); });
  world.schedule(1.0, [&] { ran.push_back(world.now()); });
  world.advance_to(0.5);
  EXPECT_TRUE(ran.empty());
  world.advance_to(3.0);
  EXPECT_EQ(ran, (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(listened, (std::vector<double>{2.0, 1.0}));
}

TEST(World, CleaningTheLastObjectFiresTheCallbackOnce) {
  World world(9);
  world.add_object(table_point(0.3, 0.0));
  int fired = 0;
  world.set_on_table_clean([&] { ++fired; });
  world.arm().take(table_point(0.3, 0.0), 0.0);
  world.arm().update(2.0);
  EXPECT_FALSE(world.table_clean());
  world.arm().put(World::bucket_position(), 2.0);
  world.arm().update(4.0);
  EXPECT_TRUE(world.table_clean());
  EXPECT_EQ(fired, 1);
}

TEST(World, FreeSpotsKeepTheSpacingAndTheZone) {
  World world(10);
  for (int i = 0; i < 8; ++i) world.add_object(world.free_spot(Zone::Hand, 0.0));
  for (const TableObject& a : world.objects()) {
    EXPECT_EQ(zone_of(distance_from_robot(a.pos)), Zone::Hand);
    EXPECT_TRUE(clear_of_boundaries(distance_from_robot(a.pos)));
    for (const TableObject& b : world.objects()) {
      if (a.id != b.id) {
        EXPECT_GE((a.pos - b.pos).norm(), kObjectSpacing);
      }
    }
  }
}

}  // namespace
}  // namespace arbc::table_clean
