#include "examples/table_clean/scenario.h"

#include <gtest/gtest.h>

#include <map>

namespace arbc::table_clean {
namespace {

std::map<Zone, int> zones(const World& world) {
  std::map<Zone, int> count;
  for (const TableObject& o : world.objects()) ++count[zone_of(distance_from_robot(o.pos))];
  return count;
}

TEST(Scenario, EveryScenarioPlacesObjectsClearOfBoundariesAndApart) {
  for (const std::string& name : scenario_names()) {
    for (uint64_t seed = 0; seed < 50; ++seed) {
      World world(seed);
      ASSERT_EQ(setup_scenario(name, world), "");
      ASSERT_GT(world.objects_total(), 0) << name;
      for (const TableObject& a : world.objects()) {
        EXPECT_TRUE(clear_of_boundaries(distance_from_robot(a.pos))) << name << " seed " << seed;
        for (const TableObject& b : world.objects()) {
          if (a.id < b.id) {
            EXPECT_GE((a.pos - b.pos).norm(), kObjectSpacing) << name;
          }
        }
      }
    }
  }
}

TEST(Scenario, ZonesPerScenario) {
  World mixed(1);
  ASSERT_EQ(setup_scenario("mixed", mixed), "");
  EXPECT_EQ(mixed.objects_total(), 10);
  EXPECT_EQ(zones(mixed),
            (std::map<Zone, int>{{Zone::Hand, 4}, {Zone::Tool, 3}, {Zone::Beyond, 3}}));
  World tool(1);
  ASSERT_EQ(setup_scenario("tool", tool), "");
  EXPECT_EQ(zones(tool), (std::map<Zone, int>{{Zone::Tool, 3}}));
  World human(1);
  ASSERT_EQ(setup_scenario("human", human), "");
  EXPECT_EQ(zones(human), (std::map<Zone, int>{{Zone::Beyond, 2}}));
  World reachable(1);
  ASSERT_EQ(setup_scenario("reachable", reachable), "");
  EXPECT_EQ(zones(reachable).size(), 1u);
  EXPECT_GE(reachable.objects_total(), 3);
  World perturbed(1);
  ASSERT_EQ(setup_scenario("perturbed", perturbed), "");
  EXPECT_TRUE(perturbed.perturbations().slip_first_put);
  EXPECT_TRUE(perturbed.perturbations().person_moves_first_rake_target);
  EXPECT_FALSE(mixed.perturbations().slip_first_put);
}

TEST(Scenario, TheSameSeedPlacesTheSameObjects) {
  World a(77), b(77);
  setup_scenario("mixed", a);
  setup_scenario("mixed", b);
  for (int i = 0; i < a.objects_total(); ++i) EXPECT_EQ(a.objects()[i].pos, b.objects()[i].pos);
}

TEST(Scenario, AnUnknownNameIsAnErrorListingTheKnownOnes) {
  World world(1);
  EXPECT_EQ(setup_scenario("mixd", world),
            "unknown scenario 'mixd' (known: reachable, tool, human, mixed, perturbed)");
  EXPECT_EQ(world.objects_total(), 0);
}

}  // namespace
}  // namespace arbc::table_clean
