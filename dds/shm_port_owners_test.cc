// A participant discovered on the shared-memory ports of one that vanished is named; one on
// the ports of one that left cleanly, or on ports of its own, is not.
#include "dds/shm_port_owners.h"

#include <gtest/gtest.h>

namespace arbc::dds {
namespace {

TEST(ShmPortOwnersTest, ARestartOnTheKilledOnesPortsIsNamed) {
  ShmPortOwners owners;
  EXPECT_FALSE(owners.discovered("a", "interop_sub", {15410, 15411}));
  // Killed: its lease has not run out yet when the new one comes.
  auto before = owners.discovered("b", "interop_sub", {15410, 15411});
  ASSERT_TRUE(before);
  EXPECT_EQ(before->name, "interop_sub");
  EXPECT_EQ(before->port, 15410u);
  // Killed again, and its lease ran out before the next one came: still its ports.
  owners.left("b", false);
  EXPECT_TRUE(owners.discovered("c", "interop_sub", {15411}));
}

TEST(ShmPortOwnersTest, PortsFreedCleanlyOrNeverHeldAreNotNamed) {
  ShmPortOwners owners;
  EXPECT_FALSE(owners.discovered("a", "p", {15410, 15411}));
  EXPECT_FALSE(owners.discovered("b", "q", {15412, 15413}));
  owners.left("a", true);
  EXPECT_FALSE(owners.discovered("c", "p", {15410, 15411}));
  // A participant announced again (the same id) is no restart.
  EXPECT_FALSE(owners.discovered("c", "p", {15410, 15411}));
}

}  // namespace
}  // namespace arbc::dds
