// Each YARP hazard arbc reports (docs/yarp.md#diagnostics), shown on real YARP: the application
// in tests/yarp_verify/<case>/ misbehaves as its diagnostic says. And the applications arbc
// proves behave as proved.
#include <gmock/gmock.h>
#include <yarp/os/Time.h>

#include "tests/yarp_real/yarp_fixture.h"

namespace arbc::yarp_test {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

class YarpApp : public YarpTest {
 protected:
  void start(const std::string& name) {
    use_folder(source_dir("tests/yarp_verify/" + name));
    connect_application(name + ".xml");
  }
};

TEST_F(YarpApp, BallLineSelectorDeliversOnlyTheSelectedTracker) {
  start("ball_line");
  send("/commander/cmd:o", "ball");
  send("/ballTracker/target:o", "1 2 3");
  send("/lineTracker/target:o", "4 5 6");
  send("/commander/cmd:o", "line");
  send("/ballTracker/target:o", "1 2 3");
  send("/lineTracker/target:o", "4 5 6");
  EXPECT_THAT(received("/controller/target:i"), ElementsAre("1 2 3", "4 5 6"));
}

TEST_F(YarpApp, FaceTrackingLooksAroundOnlyASecondAfterTheLastFace) {
  add_context("faceTracking", source_dir("tests/yarp_verify/face_tracking/contexts/faceTracking"));
  start("face_tracking");
  send("/lookAround/gaze:o", "0 0 1");
  send("/faceDetector/faces:o", "1 2 10 0.95");
  send("/lookAround/gaze:o", "0 0 2");
  send("/faceDetector/faces:o", "3 4 10 0.3");  // too uncertain: dropped
  ::yarp::os::Time::delay(1.2);
  send("/lookAround/gaze:o", "0 0 3");
  EXPECT_THAT(received("/iKinGazeCtrl/xd:i"), ElementsAre("0 0 1", "1 2 10", "0 0 3"));
}

// Refuted by arbc: each detector's unset of the other's event has no effect in YARP.
TEST_F(YarpApp, TwoSelectorsLetBothTrackersThrough) {
  start("ball_line_two_selectors");
  send("/ballDetector/seen:o", "1");
  send("/lineDetector/seen:o", "1");
  send("/ballTracker/target:o", "1 2 3");
  send("/lineTracker/target:o", "4 5 6");
  EXPECT_THAT(received("/controller/target:i"), ElementsAre("1 2 3", "4 5 6"));
}

// yarp-substring-event: with e_face and e_face_lost present, `e_face and not e_face_lost` is
// false, yet YARP delivers the face as well as the search.
TEST_F(YarpApp, SubstringEventDeliversWhatTheConstraintForbids) {
  start("substring_event");
  send("/faceDetector/status:o", "seen");
  send("/faceDetector/status:o", "lost");
  send("/faceDetector/faces:o", "face");
  send("/search/gaze:o", "search");
  EXPECT_THAT(received("/gaze/target:i"), ElementsAre("face", "search"));
}

// yarp-keyword-event: `r and not l` works, but with only `l` present `l and not r` holds, yet
// YARP drops it (`return tfalseue and not false` is nil), and the next message that passes
// another connection's accept into the port aborts the receiving process
// (docs/yarp.md#what-yarp-does).
TEST_F(YarpApp, KeywordEventNeverDeliversAndAbortsTheReceiver) {
  start("keyword_event");
  send("/arms/state:o", "none right");
  send("/planner/right:o", "reach-right");
  ::yarp::os::Time::delay(1.1);  // r expires
  send("/arms/state:o", "left none");
  send("/planner/left:o", "reach-left");
  EXPECT_THAT(received("/arms/reach:i"), ElementsAre("reach-right"));
  ASSERT_TRUE(receiver_alive());
  send("/planner/right:o", "reach-right-2");
  ::yarp::os::Time::delay(0.5);
  EXPECT_FALSE(receiver_alive());
}

// yarp-require: a monitor that does not require("yarp"), as in the paper's listings. The search
// passes while no face came; the first face crashes the receiving process (YARP hands accept a
// SWIG object whose type the monitor's Lua state does not have).
TEST_F(YarpApp, MonitorWithoutRequireCrashesTheReceiver) {
  start("require_missing");
  send("/lookAround/gaze:o", "0 0 1");
  EXPECT_THAT(received("/gaze/target:i"), ElementsAre("0 0 1"));
  ASSERT_TRUE(receiver_alive());
  send("/faceDetector/faces:o", "1 2 10");
  ::yarp::os::Time::delay(0.5);
  EXPECT_FALSE(receiver_alive());
}

// yarp-trig-interval: the watchdog's trig should run every 0.1 s and stop the base half a
// second after the last scan; it does not run, so the planner keeps driving.
TEST_F(YarpApp, TrigIntervalLetsThePlannerDriveWithoutTheLaser) {
  start("trig_interval");
  send("/laser/scan:o", "scan");
  ::yarp::os::Time::delay(1.5);
  send("/planner/cmd:o", "drive");
  send("/safety/stop:o", "stop");
  EXPECT_THAT(received("/base/laser:i"), ElementsAre("scan"));
  EXPECT_THAT(received("/base/cmd:i"), ElementsAre("drive"));
}

// yarp-event-forever: after one face, the search never resumes (its unset has no effect).
TEST_F(YarpApp, EventSetForeverBlocksTheSearchForever) {
  start("event_forever");
  send("/search/gaze:o", "search-1");
  send("/faceDetector/faces:o", "face");
  ::yarp::os::Time::delay(1.5);
  send("/search/gaze:o", "search-2");
  send("/search/gaze:o", "search-3");
  EXPECT_THAT(received("/gaze/target:i"), ElementsAre("search-1", "face"));
}

// yarp-shared-event: the arm being busy blocks head commands too (one process).
TEST_F(YarpApp, SharedEventBlocksTheOtherPort) {
  start("shared_event");
  send("/planner/head:o", "look-1");
  send("/arm/state:o", "busy");
  send("/head/state:o", "idle");
  send("/planner/head:o", "look-2");
  send("/arm/state:o", "idle");
  send("/planner/head:o", "look-3");
  EXPECT_THAT(received("/robot/head:i"), ElementsAre("look-1", "look-3"));
}

// yarp-shared-event, several setters: the left camera's e_ball has expired, the right one's is
// live, yet the ball tracker's next message is dropped (the lookup meets the expired entry
// first); the one after passes.
TEST_F(YarpApp, SeveralSettersHideALiveEventOnce) {
  start("several_setters");
  send("/leftCam/ball:o", "1");
  ::yarp::os::Time::delay(0.4);
  send("/rightCam/ball:o", "1");  // e_ball: left's until t+1.0, right's until t+1.6
  ::yarp::os::Time::delay(0.4);   // now t+1.2 or so
  send("/ballTracker/target:o", "1 2 3");
  send("/ballTracker/target:o", "4 5 6");
  EXPECT_THAT(received("/controller/target:i"), ElementsAre("4 5 6"));
}

// yarp-constraint-syntax: `e_ball && !e_line` is a Lua syntax error: the ball never passes.
TEST_F(YarpApp, ConstraintThatDoesNotParseNeverDelivers) {
  start("constraint_syntax");
  send("/commander/cmd:o", "ball");
  send("/ballTracker/target:o", "1 2 3");
  send("/commander/cmd:o", "line");
  send("/lineTracker/target:o", "4 5 6");
  EXPECT_THAT(received("/controller/target:i"), ElementsAre("4 5 6"));
}

}  // namespace
}  // namespace arbc::yarp_test
