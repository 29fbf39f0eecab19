// Generated monitors executed in a real Lua 5.4 state (not compared as text): messages go in,
// accept/update results and the events in the port's container are checked. The delivery steps
// (docs/design.md#the-message-path) are played by the harness; several monitors share one port's
// container.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include "compiler/codegen/embedded_target.h"
#include "compiler/codegen/testing/lua_monitor_harness.h"
#include "compiler/frontend/frontend.h"
#include "compiler/lower/compile_spec.h"
#include "tests/support/tree_paths.h"

namespace arbc::codegen {
namespace {

using testing::LuaMonitorHarness;
using testing::PortContainer;
using V = std::vector<std::string>;

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Builds a spec and runs any of its monitors against per-port containers.
class App {
 public:
  explicit App(const std::string& text, const std::string& script_dir = ".") {
    compiled_ = lower::compile_spec_text(text, "test.spec", script_dir);
    if (!compiled_.ok) {
      error_ = frontend::render_diagnostics(compiled_.diagnostics, &compiled_.sources);
      return;
    }
    CodegenResult r = EmbeddedTarget().generate(*compiled_.lowered);
    for (const OutputFile& f : r.files) files_[f.path] = f.content;
    if (!r.ok) error_ = "codegen failed";
  }
  const std::string& error() const { return error_; }
  const model::App& model() const { return compiled_.lowered->app; }
  PortContainer& port(const std::string& name) {
    PortContainer& p = ports_[name];
    p.set_time(now_);
    return p;
  }
  void set_time(double t) {
    now_ = t;
    for (auto& [name, p] : ports_) p.set_time(t);
  }

  // The monitor of connection `name` into `port`, loaded and created once.
  LuaMonitorHarness& monitor(const std::string& port, const std::string& name) {
    std::string key = port + "/" + name;
    auto it = monitors_.find(key);
    if (it != monitors_.end()) return *it->second;
    std::string path = "monitors/" + port + "__" + name + ".lua";
    auto h = std::make_unique<LuaMonitorHarness>(files_[path], path, &this->port(port), name);
    for (const model::Connection& c : model().connections)
      if (c.destination == port && c.name == name) h->use_model(model(), c);
    EXPECT_EQ(h->load_error(), "") << path;
    EXPECT_TRUE(h->create().ok) << path;
    return *(monitors_[key] = std::move(h));
  }

 private:
  lower::CompiledSpec compiled_;
  std::string error_;
  std::map<std::string, std::string> files_;
  std::map<std::string, PortContainer> ports_;
  std::map<std::string, std::unique_ptr<LuaMonitorHarness>> monitors_;
  double now_ = 0;
};

const char* kObjectsFarAndNear =
    "{ {pos = {x = 0.9, y = 0, z = 0}, dist = 0.9}, {pos = {x = 0.3, y = 0.1, z = 0}, dist = 0.3} "
    "}";

class TableCleanTest : public ::testing::Test {
 protected:
  TableCleanTest() : app_(read_file(arbc::testing::source_dir() + "/specs/table_clean.spec")) {}
  App app_;
};

TEST_F(TableCleanTest, StatusFeedSetsListedFlagsAndUnsetsTheOthers) {
  ASSERT_EQ(app_.error(), "");
  auto& c3 = app_.monitor("PickAndPlace.cmd", "feed_PickAndPlace_status");
  EXPECT_EQ(c3.constraint(), "false");
  auto r = c3.deliver("{ \"e_arm_idle\", \"something_else\" }");
  EXPECT_TRUE(r.ok) << r.error;
  EXPECT_FALSE(r.accepted);  // a feed never delivers
  // No lifetime in the monitor: the runtime applies app.json's (0.5 s, checked below).
  EXPECT_EQ(c3.calls(), (V{"unset e_taken", "set e_arm_idle"}));
  EXPECT_EQ(app_.port("PickAndPlace.cmd").present(), (V{"e_arm_idle"}));
  app_.set_time(0.49);
  EXPECT_EQ(app_.port("PickAndPlace.cmd").present(), (V{"e_arm_idle"}));
  app_.set_time(0.5);  // a silent module's flags lapse
  EXPECT_EQ(app_.port("PickAndPlace.cmd").present(), V{});
}

TEST_F(TableCleanTest, TakePicksTheClosestReachableObjectOnlyWhenSelected) {
  ASSERT_EQ(app_.error(), "");
  auto& take = app_.monitor("PickAndPlace.cmd", "take");
  EXPECT_EQ(
      take.constraint(),
      "not e_taken and e_arm_idle and e_pull_idle and not e_arm_pulling and not e_arm_picking");
  // Nothing in the container yet: e_arm_idle is absent, so take is not selected.
  EXPECT_EQ(take.deliver(kObjectsFarAndNear).reason, "not-selected");
  app_.monitor("PickAndPlace.cmd", "feed_PickAndPlace_status").deliver("{ \"e_arm_idle\" }");
  app_.monitor("PickAndPlace.cmd", "feed_PullObject_status").deliver("{ \"e_pull_idle\" }");
  auto r = take.deliver(kObjectsFarAndNear);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(r.accepted);
  EXPECT_EQ(r.value, "{pos={x=0.29999999999999999, y=0.10000000000000001, z=0}, verb=\"take\"}");
  // The closest object is out of hand reach: rejected by the body, not by the constraint.
  auto far = take.deliver("{ {pos = {x = 1, y = 0, z = 0}, dist = 0.5} }");
  EXPECT_FALSE(far.accepted);
  EXPECT_EQ(far.reason, "rejected");
  EXPECT_EQ(take.deliver("{}").reason, "rejected");  // `accept len(objects) > 0` guards min_by
  // The take's delivery sets e_take_open and e_arm_picking (the port's own delivery events):
  // no second take, and no put, within the arm's second.
  app_.monitor("PickAndPlace.cmd", "feed_PickAndPlace_cmd").deliver(r.value);
  EXPECT_EQ(take.deliver(kObjectsFarAndNear).reason, "not-selected");
  app_.set_time(1.0);
  // Holding an object: take is no longer selected, put is.
  app_.monitor("PickAndPlace.cmd", "feed_PickAndPlace_status")
      .deliver("{ \"e_taken\", \"e_arm_idle\" }");
  EXPECT_EQ(take.deliver(kObjectsFarAndNear).reason, "not-selected");
  auto put = app_.monitor("PickAndPlace.cmd", "put").deliver("{x = 0, y = -0.4, z = 0.1}");
  EXPECT_TRUE(put.accepted);
  EXPECT_EQ(put.value, "{pos={x=0, y=-0.40000000000000002, z=0.10000000000000001}, verb=\"put\"}");
}

TEST_F(TableCleanTest, PullCancelsWhenTheObjectIsAlreadyInHandReach) {
  ASSERT_EQ(app_.error(), "");
  app_.monitor("PullObject.cmd", "feed_PickAndPlace_status").deliver("{ \"e_arm_idle\" }");
  auto& pull = app_.monitor("PullObject.cmd", "pull");
  EXPECT_EQ(pull.deliver("{ {pos = {x = 0.6, y = 0, z = 0}, dist = 0.6} }").value,
            "{pos={x=0.59999999999999998, y=0, z=0}, verb=\"pull\"}");
  EXPECT_EQ(pull.deliver("{ {pos = {x = 0.2, y = 0, z = 0}, dist = 0.2} }").value,
            "{pos={x=0.20000000000000001, y=0, z=0}, verb=\"cancel\"}");
  EXPECT_EQ(pull.deliver("{ {pos = {x = 0.8, y = 0, z = 0}, dist = 0.8} }").reason, "rejected");
}

TEST_F(TableCleanTest, DerivedEventsFollowTheirPredicate) {
  ASSERT_EQ(app_.error(), "");
  auto& c7 = app_.monitor("HeadControl.gaze", "feed_ObjectDetector_objects");
  c7.deliver("{ {pos = {x = 0.9, y = 0, z = 0}, dist = 0.9} }");
  EXPECT_EQ(c7.calls(), (V{"set e_unreachable"}));  // no `for`: no lifetime
  app_.set_time(100);
  EXPECT_EQ(app_.port("HeadControl.gaze").present(), (V{"e_unreachable"}));
  c7.deliver(kObjectsFarAndNear);  // the closest one is reachable again
  EXPECT_EQ(app_.port("HeadControl.gaze").present(), V{});
  c7.clear_calls();
  c7.deliver("{}");  // `len(objects) > 0 and ...`: false, no missing value
  EXPECT_EQ(c7.calls(), (V{"unset e_unreachable"}));

  auto& face = app_.monitor("Speak.text", "feed_FaceDetector_face");
  face.deliver("{ pos = {x = 1, y = 0, z = 0}, certainty = 0.9 }");
  EXPECT_EQ(face.calls(), (V{"set e_face_detected"}));  // `for 1s`: app.json's lifetime
  face.deliver("{ pos = {x = 1, y = 0, z = 0}, certainty = 0.2 }");  // `for 1s`: not unset
  EXPECT_EQ(face.calls().size(), 1u);
  app_.set_time(100.5);
  EXPECT_EQ(app_.port("Speak.text").present(), (V{"e_face_detected"}));
  app_.set_time(101);
  EXPECT_EQ(app_.port("Speak.text").present(), V{});
}

TEST_F(TableCleanTest, TrackSuppressesSearchForItsHoldOnlyAfterItDelivered) {
  ASSERT_EQ(app_.error(), "");
  auto& track = app_.monitor("HeadControl.gaze", "track");
  auto& search = app_.monitor("HeadControl.gaze", "search");
  auto& head = app_.port("HeadControl.gaze");
  const char* face = "{ pos = {x = 1, y = 2, z = 3}, certainty = 0.95 }";
  const char* doubtful = "{ pos = {x = 1, y = 2, z = 3}, certainty = 0.5 }";
  auto idle = [&] {
    app_.monitor("HeadControl.gaze", "feed_PickAndPlace_status").deliver("{ \"e_arm_idle\" }");
    app_.monitor("HeadControl.gaze", "feed_PullObject_status").deliver("{ \"e_pull_idle\" }");
  };
  // `when` does not hold: track is not selected, and holds nothing off.
  EXPECT_EQ(track.deliver(face).reason, "not-selected");
  EXPECT_EQ(head.present(), V{});
  app_.monitor("HeadControl.gaze", "feed_ObjectDetector_objects")
      .deliver("{ {pos = {x = 0.9, y = 0, z = 0}, dist = 0.9} }");
  idle();
  // A face the body rejects (a joystick in its dead zone) suppresses nothing either.
  EXPECT_EQ(track.deliver(doubtful).reason, "rejected");
  EXPECT_EQ(head.present(), (V{"e_arm_idle", "e_pull_idle", "e_unreachable"}));
  auto s = search.deliver("{x = 0, y = 0, z = 1}");
  EXPECT_TRUE(s.accepted) << s.reason << s.error
                          << " present: " << ::testing::PrintToString(head.present());
  // A delivered face holds search off for the hold time; the monitor itself sets nothing.
  auto r = track.deliver(face);
  EXPECT_TRUE(r.accepted);
  EXPECT_EQ(r.value, "{x=1, y=2, z=3}");
  EXPECT_EQ(track.calls(), V{});
  EXPECT_EQ(search.deliver("{x = 0, y = 0, z = 1}").reason, "not-selected");
  app_.set_time(0.4);  // status flags refreshed, act_track still held
  idle();
  EXPECT_EQ(search.deliver("{x = 0, y = 0, z = 1}").reason, "not-selected");
  app_.set_time(1.0);  // the hold is over (status refreshed, as modules publish at 10 Hz)
  idle();
  EXPECT_TRUE(search.deliver("{x = 0, y = 0, z = 1}").accepted);
}

TEST_F(TableCleanTest, ThrottleCountsDeliveriesNotArrivals) {
  ASSERT_EQ(app_.error(), "");
  auto& ask = app_.monitor("Speak.text", "ask");
  auto& unreachable = app_.monitor("Speak.text", "feed_ObjectDetector_objects");
  auto& faces = app_.monitor("Speak.text", "feed_FaceDetector_face");
  const char* face = "{ pos = {x = 1, y = 0, z = 0}, certainty = 0.9 }";
  unreachable.deliver("{ {pos = {x = 0.9, y = 0, z = 0}, dist = 0.9} }");
  faces.deliver(face);
  auto first = ask.deliver(face);
  EXPECT_TRUE(first.accepted);
  EXPECT_EQ(first.value, "\"Please put the object closer!\"");
  app_.set_time(1);
  faces.deliver(face);
  EXPECT_EQ(ask.deliver(face).reason, "throttled");
  // At 6 s the throttle passes but the rule is not selected (the object became reachable):
  // nothing is delivered, so the throttle's clock must not restart.
  app_.set_time(6);
  faces.deliver(face);
  unreachable.deliver(kObjectsFarAndNear);
  EXPECT_EQ(ask.deliver(face).reason, "not-selected");
  app_.set_time(6.5);
  unreachable.deliver("{ {pos = {x = 0.9, y = 0, z = 0}, dist = 0.9} }");
  faces.deliver(face);
  EXPECT_TRUE(ask.deliver(face).accepted);  // counting arrivals would have throttled this
}

// ---- smaller specs for the remaining constructs ---------------------------------------------

const char* kHeader = R"(app t;
type Object = { pos: vec3, dist: float };
module Eye    { out objects: list<Object>; out face: float; }
module Head   { in gaze: vec3; in level: float; }
module Looker { out gaze: vec3; }
)";

TEST(MonitorExecTest, MissingValueRejectsWithNoValueReason) {
  App app(std::string(kHeader) + R"(
event a;
arbitrate Head.gaze { near: from Eye.objects when a { emit min_by(objects, o => o.dist).pos; } }
)");
  ASSERT_EQ(app.error(), "");
  app.port("Head.gaze").set("a", "test", std::nullopt);
  auto& near = app.monitor("Head.gaze", "near");
  auto r = near.deliver("{}");
  EXPECT_TRUE(r.ok) << r.error;  // not a script error
  EXPECT_FALSE(r.accepted);
  EXPECT_EQ(r.reason, "no-value");
  EXPECT_EQ(near.deliver("{ {pos = {x = 1, y = 2, z = 3}, dist = 1} }").value, "{x=1, y=2, z=3}");
}

TEST(MonitorExecTest, VarKeepsStateAcrossMessagesAndEveryRunsFromTrig) {
  App app(std::string(kHeader) + R"(
event a, e_seen;
arbitrate Head.level {
  count: from Eye.face when a {
    var n = 0;
    n = n + 1;
    set e_seen for 2s;
    accept n % 2 == 1;
    emit face * n;
    every 500ms { unset e_seen; }
  }
}
)");
  ASSERT_EQ(app.error(), "");
  app.port("Head.level").set("a", "test", std::nullopt);
  auto& count = app.monitor("Head.level", "count");
  EXPECT_EQ(count.trig_interval(), 0.5);
  EXPECT_EQ(count.deliver("2.0").value, "2.0");  // float * int is a float
  EXPECT_EQ(count.deliver("2.0").reason, "rejected");
  EXPECT_EQ(count.deliver("2.0").value, "6.0");
  EXPECT_EQ(count.calls(), (V{"set e_seen 2", "set e_seen 2", "set e_seen 2"}));
  EXPECT_TRUE(count.trig().ok);
  EXPECT_EQ(count.calls().back(), "unset e_seen");
}

TEST(MonitorExecTest, ScriptRunsUnderTheRulesConstraint) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "arbc_exec_script";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "double.lua") << "local calls = 0\n"
                                       "PortMonitor.accept = function(m)\n"
                                       "  calls = calls + 1\n"
                                       "  PortMonitor.setEvent(\"e_mine\", 1.0)\n"
                                       "  return m > 0\n"
                                       "end\n"
                                       "PortMonitor.update = function(m) return m * 2 end\n";
  App app(std::string(kHeader) + R"(
event a, e_mine;
arbitrate Head.level { mine: from Eye.face when a { script "double.lua"; } }
)",
          dir.string());
  ASSERT_EQ(app.error(), "");
  auto& mine = app.monitor("Head.level", "mine");
  EXPECT_EQ(mine.constraint(), "a");
  app.port("Head.level").set("a", "test", std::nullopt);
  EXPECT_EQ(mine.deliver("21").value, "42");
  EXPECT_EQ(mine.deliver("-1").reason, "rejected");
  EXPECT_EQ(mine.calls(), (V{"set e_mine 1", "set e_mine 1"}));
}

TEST(MonitorExecTest, ConnectMonitorsFilterAndTransformWithoutAConstraint) {
  App app(std::string(kHeader) + R"(
connect Looker.gaze -> Head.gaze { accept norm(gaze) > 0.5; emit gaze * 2.0; }
)");
  ASSERT_EQ(app.error(), "");
  auto& c = app.monitor("Head.gaze", "from_Looker_gaze");
  EXPECT_EQ(c.constraint(), "true");  // not arbitrated: always selected
  EXPECT_EQ(c.deliver("{x = 1, y = 0, z = 0}").value, "{x=2.0, y=0.0, z=0.0}");
  EXPECT_EQ(c.deliver("{x = 0.1, y = 0, z = 0}").reason, "rejected");
}

// ---- plausible bugs that survived mutation testing (issue 13; scripts/mutate.sh) ---------

// `by priority` with a lowest `otherwise` rule: `otherwise` is "none of the others' effective
// guards holds" AND the lowest rule is still suppressed while a higher rule's activity event
// is held. Without the `not act_track` term, search would deliver as soon as the face is lost,
// inside track's hold time.
TEST(MonitorExecTest, OtherwiseUnderPriorityIsSuppressedDuringTheHold) {
  App app(R"(app t;
module Face   { out pos: vec3; }
module Look   { out gaze: vec3; }
module Status { out flags: list<string>; }
module Head   { in gaze: vec3; }
events from Status.flags { e_face } lifetime 5s;
arbitrate Head.gaze by priority {
  track:  from Face.pos when e_face hold 1s;
  search: from Look.gaze when otherwise;
}
)");
  ASSERT_EQ(app.error(), "");
  auto& feed = app.monitor("Head.gaze", "feed_Status_flags");
  auto& track = app.monitor("Head.gaze", "track");
  auto& search = app.monitor("Head.gaze", "search");
  const char* target = "{x = 1, y = 0, z = 0}";
  EXPECT_TRUE(search.deliver(target).accepted);  // no face, nothing held: search looks around
  feed.deliver("{ \"e_face\" }");
  EXPECT_TRUE(track.deliver(target).accepted);  // act_track held for 1 s
  EXPECT_EQ(search.deliver(target).reason, "not-selected");
  app.set_time(0.1);
  feed.deliver("{}");  // the face is lost: track's `when` no longer holds
  EXPECT_EQ(track.deliver(target).reason, "not-selected");
  EXPECT_EQ(search.deliver(target).reason, "not-selected");  // but the hold still suppresses it
  app.set_time(0.9);
  EXPECT_EQ(search.deliver(target).reason, "not-selected");
  app.set_time(1.1);  // the hold is over
  EXPECT_TRUE(search.deliver(target).accepted);
}

// `!=` on vec3, records and lists compares by content, run in Lua (not only as text): equal
// values are rejected, different ones pass; `==` is its opposite.
TEST(MonitorExecTest, NotEqualOnStructuredValuesComparesContent) {
  App app(R"(app t;
type Rec = { a: int, b: string };
module Src { out p: vec3; out r: Rec; out l: list<int>; out q: vec3; }
module Dst { in p: vec3; in r: Rec; in l: list<int>; in q: vec3; }
connect Src.p -> Dst.p { accept p != vec3(1, 2, 3); }
connect Src.r -> Dst.r { accept r != { a: 1, b: "x" }; }
connect Src.l -> Dst.l { accept l != [1, 2]; }
connect Src.q -> Dst.q { accept q == vec3(1, 2, 3); }
)");
  ASSERT_EQ(app.error(), "");
  auto& p = app.monitor("Dst.p", "from_Src_p");
  EXPECT_EQ(p.deliver("{x = 1, y = 2, z = 3}").reason, "rejected");
  EXPECT_TRUE(p.deliver("{x = 1, y = 2, z = 4}").accepted);
  auto& r = app.monitor("Dst.r", "from_Src_r");
  EXPECT_EQ(r.deliver("{a = 1, b = \"x\"}").reason, "rejected");
  EXPECT_TRUE(r.deliver("{a = 1, b = \"y\"}").accepted);
  EXPECT_TRUE(r.deliver("{a = 2, b = \"x\"}").accepted);
  auto& l = app.monitor("Dst.l", "from_Src_l");
  EXPECT_EQ(l.deliver("{1, 2}").reason, "rejected");
  EXPECT_TRUE(l.deliver("{1, 2, 3}").accepted);
  EXPECT_TRUE(l.deliver("{2, 1}").accepted);
  EXPECT_TRUE(l.deliver("{}").accepted);
  auto& q = app.monitor("Dst.q", "from_Src_q");
  EXPECT_TRUE(q.deliver("{x = 1, y = 2, z = 3}").accepted);
  EXPECT_EQ(q.deliver("{x = 3, y = 2, z = 1}").reason, "rejected");
}

// Every Lua number a monitor computes has the subtype of its spec type
// (docs/design.md#numbers-at-run-time): the harness prints a float with ".0" when integral.
TEST(MonitorExecTest, NumbersKeepTheirSpecTypeAtRunTime) {
  App app(R"(app t;
module Src { out m: {i: int, f: float}; }
module Dst { in cmd: {lo: float, hi: int, v: vec3, ys: list<float>, s: float, q: float}; }
connect Src.m -> Dst.cmd {
  accept m.i <= m.f;
  emit { lo: min(m.i, 2.5), hi: max(m.i, 0), v: vec3(m.i, 0, 1.5), ys: [m.i, 2.5], s: m.i,
         q: m.i / 2 };
}
)");
  ASSERT_EQ(app.error(), "");
  auto& c = app.monitor("Dst.cmd", "from_Src_m");
  auto r = c.deliver("{i = 1, f = 1.5}");
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_TRUE(r.accepted);
  EXPECT_EQ(r.value,
            "{hi=1, lo=1.0, q=0.5, s=1.0, v={x=1.0, y=0.0, z=1.5}, ys={[1]=1.0, [2]=2.5}}");
  // Compared as floats: 2^53 + 1 is 2^53 as a float, so it is <= 2^53 (Lua would compare the
  // integer exactly and say no).
  EXPECT_TRUE(c.deliver("{i = 9007199254740993, f = 9007199254740992.0}").accepted);
}

}  // namespace
}  // namespace arbc::codegen
