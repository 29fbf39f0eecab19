#include "core/app_json.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace arbc::model {
namespace {

App small_app() {
  App app;
  app.name = "demo";
  app.description = "two sources into one port";
  app.spec_file = "specs/demo.spec";
  Module a{"A",
           "a source",
           {{"out", Direction::Out, parse_type("vec3"), {"demo.spec", 3, 12}}},
           {"demo.spec", 3, 1}};
  Module h{"H", "", {{"gaze", Direction::In, parse_type("vec3"), {}}}, {}};
  app.modules = {a, h};
  app.events.push_back({"e_face", 1.0, "", {"demo.spec", 5, 7}});
  Connection c;
  c.name = "track";
  c.source = "A.out";
  c.destination = "H.gaze";
  c.constraint = parse_constraint("not e_face or e_face_2").constraint;
  c.must_set = {"e_face"};
  c.trig_interval = 0.5;
  c.monitor = "monitors/H.gaze__track.lua";
  c.monitor_sha256 = std::string(64, 'a');
  c.sets = {"act_track", "e_face"};
  c.activity_event = "act_track";
  c.source_map = {{12, 7}, {13, 8}};
  app.connections.push_back(c);
  ArbitratedPort port;
  port.port = "H.gaze";
  port.rules = {"track"};
  port.asserts.push_back({"track", parse_constraint("e_face").constraint, {"demo.spec", 9, 1}});
  app.arbitrated_ports.push_back(port);
  app.exclusive_groups.push_back({{"e_face", "e_face_2"}, {}});
  app.invariants.push_back({parse_constraint("e_face or not e_face_2").constraint, {}});
  return app;
}

TEST(AppJsonTest, RoundTripsByteForByte) {
  std::string text = to_app_json(small_app());
  AppLoad loaded = from_app_json(text);
  ASSERT_TRUE(loaded.ok) << loaded.error;
  EXPECT_EQ(to_app_json(loaded.app), text);
  EXPECT_EQ(loaded.app.connections[0].constraint.to_string(), "not e_face or e_face_2");
  EXPECT_EQ(*loaded.app.connections[0].trig_interval, 0.5);
  EXPECT_EQ(loaded.app.modules[0].loc.line, 3);
  EXPECT_EQ(loaded.app.connections[0].source_map, (std::vector<SourceMapEntry>{{12, 7}, {13, 8}}));
  EXPECT_EQ(loaded.app.connections[0].activity_event, "act_track");
  EXPECT_EQ(loaded.app.connections[0].monitor_sha256, std::string(64, 'a'));
}

// One representation of a constraint: its text (schema version 2 dropped the tree).
TEST(AppJsonTest, AConstraintIsItsTextOnly) {
  std::string text = to_app_json(small_app());
  EXPECT_NE(text.find("\"constraint\": \"not e_face or e_face_2\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"property\": \"e_face\""), std::string::npos);
  EXPECT_NE(text.find("\"formula\": \"e_face or not e_face_2\""), std::string::npos);
  EXPECT_EQ(text.find("\"tree\""), std::string::npos);
  EXPECT_NE(text.find("\"schema_version\": 2"), std::string::npos);
}

// A monitor without its digest cannot be checked against what was built: refused.
TEST(AppJsonTest, EveryMonitorHasItsDigest) {
  std::string text = to_app_json(small_app());
  std::string bad = text;
  bad.replace(bad.find(std::string(64, 'a')), 64, "");
  EXPECT_EQ(from_app_json(bad).error,
            "connections[0].monitor_sha256: missing; every monitor has the SHA-256 `arbc build` "
            "recorded (rebuild the app)");
  bad = text;
  bad.replace(bad.find(std::string(64, 'a')), 64, std::string(64, 'A'));
  EXPECT_NE(from_app_json(bad).error.find("not 64 lower-case hex digits"), std::string::npos);
}

TEST(AppJsonTest, ErrorsNameThePathOfTheBadValue) {
  EXPECT_EQ(from_app_json("{").error,
            "not valid JSON at line 1, column 2: syntax error while parsing object key - "
            "unexpected end of input; expected string literal");
  EXPECT_EQ(from_app_json("[]").error, "app.json: expected a JSON object");
  std::string text = to_app_json(small_app());
  std::string bad = text;
  bad.replace(bad.find("\"not e_face or e_face_2\""), 24, "\"not (e_face\"");
  EXPECT_EQ(from_app_json(bad).error, "connections[0].constraint: expected ')' at offset 11");
  bad = text;
  bad.replace(bad.find("\"vec3\""), 6, "\"quat\"");
  EXPECT_EQ(from_app_json(bad).error, "modules[0].ports[0].type: unknown type 'quat'");
  bad = text;
  bad.replace(bad.find("\"schema_version\": 2"), 19, "\"schema_version\": 1");
  EXPECT_NE(from_app_json(bad).error.find("this arbc reads version 2, the file has 1"),
            std::string::npos);
}

TEST(AppJsonTest, ASyntaxErrorNamesItsLineAndColumn) {
  std::string text = to_app_json(small_app());
  size_t at = text.find("\"modules\"");
  ASSERT_NE(at, std::string::npos);
  text.insert(at, ",");  // a second comma after the previous member
  size_t line = 1 + std::count(text.begin(), text.begin() + at, '\n');
  size_t column = at - text.rfind('\n', at);
  std::string want = "not valid JSON at line " + std::to_string(line) + ", column " +
                     std::to_string(column) + ": syntax error";
  EXPECT_EQ(from_app_json(text).error.substr(0, want.size()), want);
}

}  // namespace
}  // namespace arbc::model
