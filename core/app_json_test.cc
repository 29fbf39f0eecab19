#include "core/app_json.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

namespace arbc::model {

using namespace std::chrono_literals;
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
  app.events.push_back({"e_face", 1s, "", {"demo.spec", 5, 7}});
  Connection c;
  c.name = "track";
  c.source = "A.out";
  c.destination = "H.gaze";
  c.constraint = parse_constraint("not e_face or e_face_2").constraint;
  c.must_set = {"e_face"};
  c.trig_interval = 500ms;
  c.monitor = "monitors/H.gaze__track.lua";
  c.monitor_sha256 = std::string(64, 'a');
  c.sets = {"act_track", "e_face"};
  c.activity_event = "act_track";
  c.source_map = {{12, 7}, {13, 8}};
  app.connections.push_back(c);
  ArbitratedPort port;
  port.port = "H.gaze";
  port.rules = {"track"};
  port.asserts.push_back({"track", parse_constraint("e_face").constraint, {"demo.spec", 9, 1}, {}});
  app.arbitrated_ports.push_back(port);
  app.exclusive_groups.push_back({{"e_face", "e_face_2"}, {}});
  app.invariants.push_back({parse_constraint("e_face or not e_face_2").constraint, {}});
  return app;
}

// The error from_app_json gives for `text` (empty, and a test failure, when it loads).
std::string load_error(std::string_view text) {
  std::string err;
  EXPECT_FALSE(from_app_json(text, &err)) << "loaded";
  return err;
}

TEST(AppJsonTest, RoundTripsByteForByte) {
  std::string text = to_app_json(small_app());
  std::string err;
  std::optional<App> app = from_app_json(text, &err);
  ASSERT_TRUE(app) << err;
  EXPECT_TRUE(err.empty());
  EXPECT_EQ(to_app_json(*app), text);
  EXPECT_EQ(app->connections[0].constraint.to_string(), "not e_face or e_face_2");
  EXPECT_EQ(*app->connections[0].trig_interval, 500ms);
  EXPECT_EQ(app->modules[0].loc.line, 3);
  EXPECT_EQ(app->connections[0].source_map, (std::vector<SourceMapEntry>{{12, 7}, {13, 8}}));
  EXPECT_EQ(app->connections[0].activity_event, "act_track");
  EXPECT_EQ(app->connections[0].monitor_sha256, std::string(64, 'a'));
}

// Properties over time (docs/design.md#properties-over-time) round-trip; an app without any
// writes no `temporal` key, so app.json files written before them keep their bytes.
TEST(AppJsonTest, TemporalPropertiesRoundTripAndAreOmittedWhenNone) {
  App app = small_app();
  EXPECT_EQ(to_app_json(app).find("\"temporal\""), std::string::npos);
  app.temporal.push_back({TemporalProperty::Kind::Spacing,
                          "H.gaze",
                          "track",
                          1500ms,
                          {"demo.spec", 11, 1},
                          "",
                          "",
                          false,
                          {}});
  TemporalProperty absence{
      TemporalProperty::Kind::Absence, "H.gaze", "search", 0s, {}, "", "", false, {}};
  absence.event = "act_track";
  TemporalProperty precedence{
      TemporalProperty::Kind::Precedence, "H.gaze", "search", 0s, {}, "", "", false, {}};
  precedence.other = "track";
  app.temporal.push_back(absence);
  app.temporal.push_back(precedence);
  std::string text = to_app_json(app);
  std::string err;
  std::optional<App> back = from_app_json(text, &err);
  ASSERT_TRUE(back) << err;
  ASSERT_EQ(back->temporal.size(), 3u);
  EXPECT_EQ(back->temporal[0].rule, "track");
  EXPECT_EQ(back->temporal[0].window, 1500ms);
  EXPECT_EQ(back->temporal[1].kind, TemporalProperty::Kind::Absence);
  EXPECT_EQ(back->temporal[1].event, "act_track");
  EXPECT_EQ(back->temporal[2].kind, TemporalProperty::Kind::Precedence);
  EXPECT_EQ(back->temporal[2].other, "track");
  EXPECT_NE(text.find("\"after\": \"track\""), std::string::npos) << text;
  EXPECT_EQ(to_app_json(*back), text);
  std::string bad = text;
  bad.replace(bad.find("\"spacing\""), 9, "\"nearby\"");
  EXPECT_NE(load_error(bad).find("temporal[0].kind: expected \"spacing\", \"absence\""),
            std::string::npos);
  bad = text;
  bad.replace(bad.find("\"after\""), 7, "\"later\"");
  EXPECT_NE(load_error(bad).find("temporal[2]"), std::string::npos);
}

// Environment assumptions (docs/app-json.md#assumptions) round-trip, `until` optional; none
// writes no `assumptions` key.
TEST(AppJsonTest, AssumptionsRoundTripAndAreOmittedWhenNone) {
  App app = small_app();
  EXPECT_EQ(to_app_json(app).find("\"assumptions\""), std::string::npos);
  app.assumptions.push_back(
      {"e_face", "H.gaze", "track", "search", {"demo.spec", 12, 1}, std::nullopt});
  app.assumptions.push_back(
      {"e_face_2", "H.gaze", "track", "", {"demo.spec", 13, 1}, std::nullopt});
  app.assumptions.push_back({"e_idle", "H.gaze", "track", "", {"demo.spec", 14, 1}, 1500ms});
  std::string text = to_app_json(app);
  std::string err;
  std::optional<App> back = from_app_json(text, &err);
  ASSERT_TRUE(back) << err;
  ASSERT_EQ(back->assumptions.size(), 3u);
  EXPECT_EQ(back->assumptions[0].event, "e_face");
  EXPECT_EQ(back->assumptions[0].after, "track");
  EXPECT_EQ(back->assumptions[0].until, "search");
  EXPECT_FALSE(back->assumptions[0].absent_for);
  EXPECT_EQ(back->assumptions[1].until, "");
  EXPECT_EQ(back->assumptions[1].loc.line, 13);
  EXPECT_EQ(back->assumptions[2].absent_for, 1500ms);
  EXPECT_EQ(to_app_json(*back), text);
  std::string bad = text;
  bad.replace(bad.find("\"after\""), 7, "\"later\"");
  EXPECT_NE(load_error(bad).find("assumptions[0]"), std::string::npos);
  // The timed form: a positive period, and no `until` beside it.
  const std::string timed = "\"absent_for\": 1.5";
  std::string zero = text;
  zero.replace(zero.find(timed), timed.size(), "\"absent_for\": 0");
  EXPECT_NE(load_error(zero).find("assumptions[2].absent_for: expected a positive number"),
            std::string::npos)
      << load_error(zero);
  std::string both = text;
  both.replace(both.find(timed), timed.size(), timed + ", \"until\": \"x\"");
  EXPECT_NE(load_error(both).find("not both"), std::string::npos) << load_error(both);
}

// Response, stability and rates (`given M.p every D`) round-trip; no rates, no `rates` key; a
// rate that is not a positive number of seconds is bad input naming where.
TEST(AppJsonTest, ResponseStabilityAndRatesRoundTrip) {
  App app = small_app();
  EXPECT_EQ(to_app_json(app).find("\"rates\""), std::string::npos);
  TemporalProperty response{
      TemporalProperty::Kind::Response, "H.gaze", "search", 1200ms, {}, "", "track", true, {}};
  response.condition = parse_constraint("e_idle and not e_busy").constraint;
  TemporalProperty stability{
      TemporalProperty::Kind::Stability, "H.gaze", "", 500ms, {}, "", "", false, {}};
  app.temporal = {response, stability};
  app.rates.push_back({"L.gaze", 200ms, {"demo.spec", 4, 1}});
  std::string text = to_app_json(app);
  std::string err;
  std::optional<App> back = from_app_json(text, &err);
  ASSERT_TRUE(back) << err;
  ASSERT_EQ(back->temporal.size(), 2u);
  EXPECT_EQ(back->temporal[0].kind, TemporalProperty::Kind::Response);
  EXPECT_EQ(back->temporal[0].other, "track");
  EXPECT_TRUE(back->temporal[0].stops);
  EXPECT_EQ(back->temporal[0].window, 1200ms);
  EXPECT_EQ(back->temporal[0].condition.to_string(), "e_idle and not e_busy");
  EXPECT_EQ(back->temporal[1].kind, TemporalProperty::Kind::Stability);
  EXPECT_EQ(back->temporal[1].window, 500ms);
  EXPECT_TRUE(back->temporal[1].rule.empty());
  ASSERT_EQ(back->rates.size(), 1u);
  EXPECT_EQ(back->rates[0].port, "L.gaze");
  EXPECT_EQ(back->rates[0].period, 200ms);
  EXPECT_EQ(back->rates[0].loc.line, 4);
  ASSERT_NE(back->find_rate("L.gaze"), nullptr);
  EXPECT_EQ(back->find_rate("H.gaze"), nullptr);
  EXPECT_EQ(to_app_json(*back), text);
  std::string bad = text;
  bad.replace(bad.find("\"every\": 0.2"), 12, "\"every\": -1");
  EXPECT_NE(load_error(bad).find("rates[0].every: expected a positive number of seconds"),
            std::string::npos)
      << load_error(bad);
}

// A response triggered by an event and answered by any rule of its port round-trips; one
// trigger, never both or none, and `stops` only with a trigger rule.
TEST(AppJsonTest, AResponseToAnEventAnsweredByThePortRoundTrips) {
  App app = small_app();
  TemporalProperty response{
      TemporalProperty::Kind::Response, "H.gaze", "", 100ms, {}, "e_lost", "", false, {}};
  app.temporal = {response};
  std::string text = to_app_json(app);
  std::string err;
  std::optional<App> back = from_app_json(text, &err);
  ASSERT_TRUE(back) << err;
  ASSERT_EQ(back->temporal.size(), 1u);
  EXPECT_EQ(back->temporal[0].event, "e_lost");
  EXPECT_TRUE(back->temporal[0].other.empty());
  EXPECT_TRUE(back->temporal[0].rule.empty());
  EXPECT_EQ(to_app_json(*back), text);
  std::string both = text;
  const std::string trigger = R"("event": "e_lost")";
  both.replace(both.find(trigger), trigger.size(), trigger + R"(, "after": "x")");
  EXPECT_NE(load_error(both).find("expected one trigger"), std::string::npos) << load_error(both);
  std::string none = text;
  none.replace(none.find(trigger), trigger.size(), R"("x": 1)");
  EXPECT_NE(load_error(none).find("expected one trigger"), std::string::npos) << load_error(none);
  std::string stops = text;
  stops.replace(stops.find(R"("stops": false)"), 14, R"("stops": true)");
  EXPECT_NE(load_error(stops).find("`stops` needs a trigger rule"), std::string::npos)
      << load_error(stops);
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
  EXPECT_EQ(load_error(bad),
            "connections[0].monitor_sha256: missing; every monitor has the SHA-256 `arbc build` "
            "recorded (rebuild the app)");
  bad = text;
  bad.replace(bad.find(std::string(64, 'a')), 64, std::string(64, 'A'));
  EXPECT_NE(load_error(bad).find("not 64 lower-case hex digits"), std::string::npos);
}

TEST(AppJsonTest, ErrorsNameThePathOfTheBadValue) {
  EXPECT_EQ(load_error("{"),
            "line 1, column 2: not valid JSON: syntax error while parsing object key - "
            "unexpected end of input; expected string literal");
  EXPECT_EQ(load_error("[]"), "app.json: expected a JSON object");
  std::string text = to_app_json(small_app());
  std::string bad = text;
  bad.replace(bad.find("\"not e_face or e_face_2\""), 24, "\"not (e_face\"");
  EXPECT_EQ(load_error(bad), "connections[0].constraint: expected ')' at offset 11");
  bad = text;
  bad.replace(bad.find("\"vec3\""), 6, "\"quat\"");
  EXPECT_EQ(load_error(bad), "modules[0].ports[0].type: unknown type 'quat'");
  bad = text;
  bad.replace(bad.find("\"schema_version\": 2"), 19, "\"schema_version\": 1");
  EXPECT_NE(load_error(bad).find("this arbc reads version 2, the file has 1"), std::string::npos);
}

// Each section of the file names the path of its bad value (one reader per section).
TEST(AppJsonTest, EverySectionNamesThePathOfItsBadValue) {
  using Json = nlohmann::ordered_json;
  const Json good = Json::parse(to_app_json(small_app()));
  auto with = [&](const std::string& pointer, const Json& value) {
    Json bad = good;
    bad[Json::json_pointer(pointer)] = value;
    return load_error(bad.dump(2));
  };
  auto without = [&](const std::string& key) {
    Json bad = good;
    bad.erase(key);
    return load_error(bad.dump(2));
  };
  EXPECT_EQ(without("modules"), "app.json: missing \"modules\"");
  EXPECT_EQ(without("connections"), "app.json: missing \"connections\"");
  EXPECT_EQ(with("/modules/0", 7), "modules[0]: expected an object");
  EXPECT_EQ(with("/modules/0/ports/0/direction", "up"),
            "modules[0].ports[0].direction: expected \"in\" or \"out\"");
  EXPECT_EQ(with("/modules/0/loc/line", "3"), "modules[0].loc.line: expected an integer");
  EXPECT_EQ(with("/events/0/lifetime", true),
            "events[0].lifetime: expected a number of seconds or null");
  // Not a whole number of nanoseconds, the runtime's and the proof's unit (core/instant.h), or
  // no time at all, or longer than 100 years: refused, never rounded.
  EXPECT_EQ(with("/events/0/lifetime", 1e-10),
            "events[0].lifetime: 0.0000000001 seconds is not a whole number of nanoseconds: write "
            "at most 9 digits after the point");
  EXPECT_EQ(with("/events/0/lifetime", 0.1234567891),
            "events[0].lifetime: 0.1234567891 seconds is not a whole number of nanoseconds: write "
            "at most 9 digits after the point");
  EXPECT_EQ(with("/connections/0/throttle", 1.0000000001),
            "connections[0].throttle: 1.0000000001 seconds is not a whole number of nanoseconds: "
            "write at most 9 digits after the point");
  EXPECT_EQ(with("/events/0/lifetime", 0),
            "events[0].lifetime: expected a positive number of seconds");
  EXPECT_EQ(with("/connections/0/trig_interval", 4e9),
            "connections[0].trig_interval: expected at most 3155760000 seconds (100 years)");
  EXPECT_EQ(with("/connections/0/kind", "rul"),
            "connections[0].kind: expected \"rule\", \"feed\" or \"connect\"");
  EXPECT_EQ(with("/connections/0/opaque", 0), "connections[0].opaque: expected true or false");
  EXPECT_EQ(with("/connections/0/sets/1", 2), "connections[0].sets[1]: expected a string");
  EXPECT_EQ(with("/connections/0/source_map/0", Json::array({12})),
            "connections[0].source_map[0]: expected [monitor_line, spec_line]");
  EXPECT_EQ(with("/arbitrated_ports/0/asserts/0/property", "e_face and"),
            "arbitrated_ports[0].asserts[0].property: expected an event name, 'not', 'true', "
            "'false' or '(' at offset 10");
  EXPECT_EQ(with("/exclusive_groups/0/events", "e_face"),
            "exclusive_groups[0].events: expected an array");
  EXPECT_EQ(with("/invariants/0", Json::object()), "invariants[0]: missing \"formula\"");
}

TEST(AppJsonTest, ASyntaxErrorNamesItsLineAndColumn) {
  std::string text = to_app_json(small_app());
  size_t at = text.find("\"modules\"");
  ASSERT_NE(at, std::string::npos);
  text.insert(at, ",");  // a second comma after the previous member
  size_t line = 1 + std::count(text.begin(), text.begin() + at, '\n');
  size_t column = at - text.rfind('\n', at);
  std::string want = "line " + std::to_string(line) + ", column " + std::to_string(column) +
                     ": not valid JSON: syntax error";
  EXPECT_EQ(load_error(text).substr(0, want.size()), want);
}

// "line:column: message" of the error from_app_json gives for `text` read from a file, as
// render() heads it; a test failure when it loads.
std::string placed_error(std::string_view text) {
  Diagnostic d;
  EXPECT_FALSE(from_app_json(text, "out/demo/app.json", &d)) << "loaded";
  EXPECT_EQ(d.loc.file.str(), "out/demo/app.json");
  EXPECT_EQ(d.id, "app-json");
  return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " + d.message;
}

// "line:column" of the first occurrence of `needle` in `text`.
std::string place_of(const std::string& text, const std::string& needle) {
  size_t at = text.find(needle);
  if (at == std::string::npos) return "no " + needle;
  size_t line = 1 + std::count(text.begin(), text.begin() + at, '\n');
  size_t line_start = text.rfind('\n', at);
  size_t column = line_start == std::string::npos ? at + 1 : at - line_start;
  return std::to_string(line) + ":" + std::to_string(column);
}

// Read from a file, each error is at its place in the file: a syntax error at its character, a
// value of the wrong kind at the value, a missing value at the object that lacks it, a repeated
// key at the second one. The message is the one the path-naming form gives.
TEST(AppJsonTest, AFilesErrorsAreAtTheirPlace) {
  EXPECT_EQ(placed_error("{\n  \"schema_version\": 2,\n  \"name\": \"x\",,\n}\n"),
            "3:15: not valid JSON: syntax error while parsing object key - unexpected ','; "
            "expected string literal");
  EXPECT_EQ(placed_error("\n  []"), "2:3: expected a JSON object");

  using Json = nlohmann::ordered_json;
  const Json good = Json::parse(to_app_json(small_app()));
  Json bad = good;
  bad["modules"][0]["ports"][0]["direction"] = "up";
  std::string text = bad.dump(2);
  EXPECT_EQ(placed_error(text), place_of(text, "\"up\"") +
                                    ": modules[0].ports[0].direction: expected \"in\" or \"out\"");

  bad = good;
  bad["schema_version"] = 7;
  text = bad.dump(2);
  EXPECT_EQ(placed_error(text), place_of(text, "7") +
                                    ": schema_version: this arbc reads version 2, the file has 7; "
                                    "rebuild it with this arbc");

  bad = good;  // missing: at the object without it, here the second module
  bad["modules"][1].erase("name");
  text = bad.dump(2);
  size_t module = text.rfind("\n    {", text.find("\"gaze\"")) + 5;  // its port's name
  EXPECT_EQ(placed_error(text),
            place_of(text, text.substr(module, 20)) + ": modules[1]: missing \"name\"");

  bad = good;
  bad.erase("connections");
  text = bad.dump(2);
  EXPECT_EQ(placed_error(text), "1:1: missing \"connections\"");

  // A duration with ten digits after the point, at its value (docs/app-json.md#durations).
  text = to_app_json(small_app());
  const std::string interval = "\"trig_interval\": 0.5";
  text.replace(text.find(interval), interval.size(), "\"trig_interval\": 0.5000000001");
  EXPECT_EQ(placed_error(text), place_of(text, "0.5000000001") +
                                    ": connections[0].trig_interval: 0.5000000001 seconds is not "
                                    "a whole number of nanoseconds: write at most 9 digits after "
                                    "the point");

  text = to_app_json(small_app());  // the app's "name" twice
  std::string first = place_of(text, "\"name\"");
  text.insert(text.find('\n', text.find("\"name\"")) + 1, "  \"name\": \"again\",\n");
  std::string want = place_of(text, "\"name\": \"again\"") +
                     ": key \"name\" repeated in one object (the first is at line " +
                     first.substr(0, first.find(':')) + ")";
  EXPECT_EQ(placed_error(text).substr(0, want.size()), want);
}

}  // namespace
}  // namespace arbc::model
