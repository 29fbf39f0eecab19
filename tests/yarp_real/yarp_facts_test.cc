// What YARP 3.12's portmonitor carrier does, checked on real YARP (docs/yarp.md#what-yarp-does
// cites these tests). Monitors are in tests/yarp_real/facts/.
#include <gmock/gmock.h>
#include <yarp/os/Time.h>

#include "tests/yarp_real/yarp_fixture.h"

namespace arbc::yarp_test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

constexpr const char* kMonitor = "tcp+recv.portmonitor+type.lua+file.";

class YarpFacts : public YarpTest {
 protected:
  void SetUp() override {
    YarpTest::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    use_folder(source_dir("tests/yarp_real/facts"));
  }
  // A connection from a new writer to the receiver's port `to` with monitor `script`.
  void monitored(const std::string& from, const std::string& to, const std::string& script) {
    writer(from);
    ASSERT_TRUE(connect(from, to, kMonitor + script));
  }
};

// create(options) gets source, destination, carrier...; accept then update run per message;
// the data is a yarp.Bottle reached with thing:asBottle().
// The carrier option is the whole carrier string.
TEST_F(YarpFacts, CreateAcceptUpdateAndTheirArguments) {
  start_receiver({"/r/d"});
  monitored("/w/a", "/r/d", "callbacks");
  send("/w/a", "hello");
  send("/w/a", "again");
  std::vector<std::string> got = received("/r/d");
  ASSERT_EQ(got.size(), 2u);
  EXPECT_THAT(got[0], HasSubstr(R"(hello "create=yes" "accepts=1" "source=/w/a" )"
                                R"("destination=/r/d" )"
                                R"("carrier=tcp+recv.portmonitor+type.lua+file.callbacks" )"
                                R"("type=lua" "sender_side=0" "receiver_side=1" )"
                                R"("filename_ends=true")"));
  EXPECT_THAT(got[1], HasSubstr(R"(again "create=yes" "accepts=2")"));
}

// Each connection has its own Lua state: the same script's globals are not shared.
TEST_F(YarpFacts, OneLuaStatePerConnection) {
  start_receiver({"/r/d"});
  monitored("/w/a", "/r/d", "counter");
  monitored("/w/b", "/r/d", "counter");
  send("/w/a", "a");
  send("/w/a", "a");
  send("/w/b", "b");
  std::vector<std::string> got = received("/r/d");
  EXPECT_THAT(got, ElementsAre("a 1", "a 2", "b 1"));
}

// Events are one table per process: an event set by a monitor on a connection into one port
// is seen by a constraint on a connection into another port of the same process.
TEST_F(YarpFacts, EventsArePerProcessNotPerPort) {
  start_receiver({"/r/p", "/r/q"});
  monitored("/w/set", "/r/p", "set_on_message");
  monitored("/w/data", "/r/q", "require_e_pw");
  send("/w/data", "before");
  send("/w/set", "set e_pw");
  send("/w/data", "after");
  EXPECT_THAT(received("/r/q"), ElementsAre("after"));
  EXPECT_THAT(received("/r/p"), IsEmpty());  // accept returned false: never delivered
}

// unsetEvent removes only the calling monitor's own copy of an event.
TEST_F(YarpFacts, UnsetRemovesOnlyTheCallersOwnEvent) {
  start_receiver({"/r/d"});
  monitored("/w/owner", "/r/d", "set_on_message");
  monitored("/w/other", "/r/d", "set_on_message_b");
  monitored("/w/data", "/r/d", "require_e_own");
  send("/w/owner", "set e_own");
  send("/w/other", "unset e_own");
  send("/w/data", "still");
  send("/w/owner", "unset e_own");
  send("/w/data", "gone");
  EXPECT_THAT(received("/r/d"), ElementsAre("still"));
}

// hasEvent finds the first entry of a name (any owner); if it has expired it is erased and the
// answer is false, even when another owner's entry of that name is live.
TEST_F(YarpFacts, AnExpiredEntryHidesALiveOneOnce) {
  start_receiver({"/r/d"});
  monitored("/w/short", "/r/d", "set_on_message");
  monitored("/w/long", "/r/d", "set_on_message_b");
  monitored("/w/data", "/r/d", "require_e_q");
  send("/w/short", "set e_q 1.0");
  send("/w/long", "set e_q");
  send("/w/data", "live");
  ::yarp::os::Time::delay(1.2);
  send("/w/data", "first");
  send("/w/data", "second");
  EXPECT_THAT(received("/r/d"), ElementsAre("live", "second"));
}

// A one-word constraint can be given in the carrier (+constraint.WORD); YARP turns every '.'
// into a space, so `+constraint.not.e_x` is read as the constraint "not" and never selects.
TEST_F(YarpFacts, ConstraintInTheCarrierString) {
  start_receiver({"/r/d"});
  writer("/w/set");
  writer("/w/one");
  writer("/w/two");
  ASSERT_TRUE(connect("/w/set", "/r/d", std::string(kMonitor) + "set_on_message"));
  ASSERT_TRUE(connect("/w/one", "/r/d", std::string(kMonitor) + "plain+constraint.e_c"));
  ASSERT_TRUE(connect("/w/two", "/r/d", std::string(kMonitor) + "plain+constraint.not.e_x"));
  send("/w/one", "one-before");
  send("/w/two", "two-before");
  send("/w/set", "set e_c");
  send("/w/one", "one-after");
  send("/w/two", "two-after");
  EXPECT_THAT(received("/r/d"), ElementsAre("one-after"));
}

// setTrigInterval(x) starts a thread whose period is (int)(x * 1000) seconds: asked for 5 ms,
// trig runs once at the start and then not for 5 s.
TEST_F(YarpFacts, SetTrigIntervalTakesMillisecondsAsSeconds) {
  start_receiver({"/r/d"});
  monitored("/w/timed", "/r/d", "trig_counter");
  ::yarp::os::Time::delay(1.5);  // 300 periods of 5 ms
  send("/w/timed", "t");
  std::vector<std::string> got = received("/r/d");
  ASSERT_EQ(got.size(), 1u);
  int trigs = std::stoi(got[0].substr(2));
  EXPECT_EQ(trigs, 1) << got[0];  // the one call at the start
}

// trig() of every other monitor into the same port runs when a message arrives.
TEST_F(YarpFacts, TrigRunsOnThePeersOfAConnectionWhenAMessageArrives) {
  start_receiver({"/r/d"});
  monitored("/w/counted", "/r/d", "trig_counter");
  monitored("/w/other", "/r/d", "plain");
  send("/w/other", "x");
  send("/w/other", "y");
  send("/w/other", "z");
  send("/w/counted", "c");
  EXPECT_THAT(received("/r/d"), ElementsAre("x", "y", "z", "c 3"));
}

// create must return a true value: otherwise the connection is made (connect reports success)
// but the monitor is not ready, and no message passes.
TEST_F(YarpFacts, CreateMustReturnTrue) {
  start_receiver({"/r/d"});
  writer("/w/a");
  EXPECT_TRUE(connect("/w/a", "/r/d", std::string(kMonitor) + "no_create_result"));
  send("/w/a", "lost");
  EXPECT_THAT(received("/r/d"), IsEmpty());
}

// `e1 or e10` with only e10 present: YARP runs `return false or false0`, which is nil, not a
// boolean; the message is dropped and the nil stays on the monitor's Lua stack, so the next
// lookup of one of its callbacks (its trig, when a message passes the accept of another
// connection into the port) raises outside any protected call and the receiving process aborts.
TEST_F(YarpFacts, ANonBooleanConstraintAbortsTheReceivingProcess) {
  start_receiver({"/r/d"});
  monitored("/w/set", "/r/d", "set_on_message");
  monitored("/w/data", "/r/d", "require_e1_or_e10");
  monitored("/w/other", "/r/d", "plain");
  send("/w/set", "set e10");
  send("/w/data", "dropped");
  send("/w/set", "set e11");  // its accept returns false: the peers' trig do not run
  ASSERT_TRUE(receiver_alive());
  send("/w/other", "kills");
  ::yarp::os::Time::delay(0.5);
  EXPECT_FALSE(receiver_alive());
  EXPECT_THAT(received("/r/d"), IsEmpty());  // "kills" never arrived
}

// A constraint that is not Lua: YARP drops the message and leaves the error message on the
// monitor's Lua stack, where the next lookup of a callback indexes the string instead of the
// PortMonitor table: the monitor's trig (and accept, update) are no longer found.
TEST_F(YarpFacts, AConstraintThatIsNotLuaDisablesTheMonitorsCallbacks) {
  start_receiver({"/r/d"});
  monitored("/w/bad", "/r/d", "bad_constraint_trig");
  monitored("/w/data", "/r/d", "require_e_trig");
  send("/w/data", "b1");         // the bad monitor's trig runs first and sets e_trig
  ::yarp::os::Time::delay(0.4);  // e_trig expires
  send("/w/bad", "a1");          // its constraint fails to compile
  send("/w/data", "b2");         // its trig is not found any more: e_trig stays unset
  EXPECT_THAT(received("/r/d"), ElementsAre("b1"));
  EXPECT_TRUE(receiver_alive());
}

// PortMonitor has setConstraint, getConstraint, setEvent, unsetEvent, setTrigInterval;
// getConstraint returns nothing; yarp.Time_now is nil in the SWIG 4.1 bindings, yarp.now()
// works; an error in accept drops that message only.
TEST_F(YarpFacts, TheLuaApi) {
  start_receiver({"/r/d"});
  monitored("/w/a", "/r/d", "api");
  send("/w/a", "boom");
  send("/w/a", "ok");
  std::vector<std::string> got = received("/r/d");
  ASSERT_EQ(got.size(), 1u);
  EXPECT_THAT(got[0], HasSubstr(R"(ok "getConstraint_values=0")"));
  EXPECT_THAT(got[0],
              HasSubstr(R"("functions=getConstraint,setConstraint,setEvent,setTrigInterval,)"
                        R"(unsetEvent")"));
  EXPECT_THAT(got[0], HasSubstr(R"("Time_now=nil" "now=number")"));
}

}  // namespace
}  // namespace arbc::yarp_test
