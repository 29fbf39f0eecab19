#include "core/event_facts.h"

#include <gtest/gtest.h>

namespace arbc::model {
namespace {

// Two arbitrated ports, L.cmd and R.cmd, and the modules around them: a status source S.status,
// two command sources, and whatever connections a test adds.
App two_ports() {
  App app;
  app.modules = {
      {"S", "", {{"status", Direction::Out, nullptr, {}}}, {}},
      {"C", "", {{"a", Direction::Out, nullptr, {}}, {"b", Direction::Out, nullptr, {}}}, {}},
      {"L", "", {{"cmd", Direction::In, nullptr, {}}}, {}},
      {"R", "", {{"cmd", Direction::In, nullptr, {}}}, {}}};
  app.arbitrated_ports = {{"L.cmd", false, false, {}, {}, {}}, {"R.cmd", false, false, {}, {}, {}}};
  return app;
}

Connection feed(std::string source, std::string into, std::vector<std::string> sets) {
  Connection c;
  c.name = "feed_" + source;
  c.source = std::move(source);
  c.destination = std::move(into);
  c.kind = ConnectionKind::Feed;
  c.sets = std::move(sets);
  return c;
}

Connection rule(std::string name, std::string source, std::string into) {
  Connection c;
  c.name = std::move(name);
  c.source = std::move(source);
  c.destination = std::move(into);
  return c;
}

TEST(EventFactsTest, AStatusFlagFedIntoTwoPortsIsTwoFacts) {
  // Each port's feed takes a status message in its own task: a decision may fall between them.
  App app = two_ports();
  app.connections = {feed("S.status", "L.cmd", {"e_idle"}), feed("S.status", "R.cmd", {"e_idle"})};
  EXPECT_FALSE(one_fact(app, "e_idle", "L.cmd", "R.cmd"));
  EXPECT_TRUE(one_fact(app, "e_idle", "L.cmd", "L.cmd"));
  EXPECT_EQ(ports_holding(app, "e_idle"), (std::vector<std::string>{"L.cmd", "R.cmd"}));
}

TEST(EventFactsTest, AnEventAMonitorSetsLivesInItsOwnPortOnly) {
  App app = two_ports();
  Connection left = rule("left", "C.a", "L.cmd");
  left.sets = {"e_busy"};
  app.connections = {left, rule("right", "C.b", "R.cmd")};
  EXPECT_EQ(ports_holding(app, "e_busy"), std::vector<std::string>{"L.cmd"});
  EXPECT_FALSE(one_fact(app, "e_busy", "L.cmd", "R.cmd"));
  // Another rule of R.cmd setting the same name makes it a second fact, not the same one.
  Connection other = rule("other", "C.a", "R.cmd");
  other.sets = {"e_busy"};
  app.connections.push_back(other);
  EXPECT_FALSE(one_fact(app, "e_busy", "L.cmd", "R.cmd"));
}

TEST(EventFactsTest, ADeliveryEventFedIntoTwoPortsIsOneFact) {
  // Both feeds run in the task of the delivery into L.cmd (docs/design.md#delivery-events).
  App app = two_ports();
  app.connections = {rule("left", "C.a", "L.cmd"), feed("L.cmd", "R.cmd", {"e_moving"}),
                     feed("L.cmd", "L.cmd", {"e_moving"})};
  EXPECT_TRUE(is_delivery_feed(app, app.connections[1]));
  EXPECT_FALSE(is_delivery_feed(app, app.connections[0]));
  EXPECT_TRUE(one_fact(app, "e_moving", "L.cmd", "R.cmd"));
  // A monitor that also sets it into R.cmd makes R's copy its own fact again.
  Connection right = rule("right", "C.b", "R.cmd");
  right.opaque = true;  // a script may set any event of its port
  app.connections.push_back(right);
  EXPECT_FALSE(one_fact(app, "e_moving", "L.cmd", "R.cmd"));
}

}  // namespace
}  // namespace arbc::model
