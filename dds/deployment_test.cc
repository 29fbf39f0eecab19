// The deployment file: what it accepts, and the errors a user sees for what it does not.
#include "dds/deployment.h"

#include <gtest/gtest.h>

namespace arbc::dds {
namespace {

model::App two_port_app() {
  model::App app;
  app.name = "demo";
  model::Module m;
  m.name = "Base";
  m.ports.push_back(
      {"cmd_vel", model::Direction::In, parse_type("{linear: vec3, angular: vec3}"), {}});
  m.ports.push_back({"odom", model::Direction::Out, parse_type("vec3"), {}});
  app.modules.push_back(m);
  app.types.push_back({"Twist", parse_type("{linear: vec3, angular: vec3}"), {}});
  return app;
}

// The errors as `arbc run` prints them, without the quoted lines: "file:line:col: message".
std::string text_of(const std::vector<Diagnostic>& errors) {
  return deployment_errors_text(errors);
}

TEST(DeploymentTest, ReadsEveryKey) {
  Deployment d;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(parse_deployment(R"({"domain": 7, "ros2": true,
      "topics": {"Base.cmd_vel": "/cmd_vel"},
      "types": {"Twist": "geometry_msgs/msg/Twist"}, "qos": {"depth": 12,
      "ports": {"Base.odom": {"reliability": "best_effort", "durability": "transient_local"}}}})",
                               "d.json", &d, &errors))
      << text_of(errors);
  EXPECT_EQ(d.domain, 7);
  EXPECT_TRUE(d.ros2);
  EXPECT_EQ(d.topics.at("Base.cmd_vel"), "/cmd_vel");
  EXPECT_EQ(d.types.at("Twist"), "geometry_msgs/msg/Twist");
  EXPECT_EQ(d.depth, 12);
  EXPECT_TRUE(d.qos_of("Base.odom").best_effort);
  EXPECT_TRUE(d.qos_of("Base.odom").transient_local);
  EXPECT_FALSE(d.qos_of("Base.cmd_vel").best_effort);  // not given: reliable, volatile
  EXPECT_FALSE(d.qos_of("Base.cmd_vel").transient_local);
  EXPECT_TRUE(check_deployment(d, two_port_app(), &errors)) << text_of(errors);
}

TEST(DeploymentTest, DefaultsWithoutKeys) {
  Deployment d;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(parse_deployment("{}", "d.json", &d, &errors)) << text_of(errors);
  EXPECT_FALSE(d.domain);
  EXPECT_FALSE(d.ros2);
  EXPECT_EQ(d.depth, kDefaultDepth);
  EXPECT_TRUE(d.status);  // the live status is on unless the file says not
  EXPECT_EQ(d.diagnostics_topic, "/diagnostics");
}

TEST(DeploymentTest, ReadsTheStatusTopics) {
  Deployment d;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(parse_deployment(R"({"status": {"diagnostics": "/robot/diagnostics",
      "topics": {"Base.cmd_vel": "/mux/active"}}})",
                               "d.json", &d, &errors))
      << text_of(errors);
  EXPECT_TRUE(d.status);
  EXPECT_EQ(d.diagnostics_topic, "/robot/diagnostics");
  EXPECT_EQ(d.status_topics.at("Base.cmd_vel"), "/mux/active");
  model::App app = two_port_app();
  app.arbitrated_ports.push_back({});
  app.arbitrated_ports.back().port = "Base.cmd_vel";
  EXPECT_TRUE(check_deployment(d, app, &errors)) << text_of(errors);
  Deployment off;
  ASSERT_TRUE(parse_deployment(R"({"status": false})", "d.json", &off, &errors));
  EXPECT_FALSE(off.status);
}

// Each bad file names the file, the line and column of the offending key or value (of the
// offending character, for JSON that does not parse), and what is expected.
TEST(DeploymentTest, BadFilesSayWhatIsWrongAndWhere) {
  struct Case {
    const char* text;
    const char* expected;
  } cases[] = {
      {"{\n  \"domain\": 7,\n  \"ros2\": tru\n}",
       "d.json:3:14: not valid JSON: syntax error while parsing value - invalid literal"},
      {"{\"a\": 1,\n  \"b\": 1e999}",
       "d.json:2:8: not valid JSON: number overflow parsing '1e999' (beyond the range of a "
       "double)"},
      {R"({"domian": 7})",
       "d.json:1:2: unknown key \"domian\"; did you mean \"domain\"? (the keys are: domain, "
       "ros2, topics, types, qos, status; docs/distributed.md#the-deployment-file)"},
      {R"({"status": "off"})", "d.json:1:12: status: expected false (no status topics) or an "},
      {R"({"status": {"diagnostic": "/d"}})",
       "d.json:1:13: status: unknown key \"diagnostic\"; did you mean \"diagnostics\"? (the "
       "status keys are: diagnostics, topics)"},
      {R"({"status": {"diagnostics": ""}})",
       "d.json:1:28: status: diagnostics: expected a non-empty topic name"},
      {"{\n  \"ros2\": true,\n  \"domain\": -1\n}",
       "d.json:3:13: domain: expected an integer from 0 to 232"},
      {R"({"domain": 1.5})", "d.json:1:12: domain: expected an integer from 0 to 232"},
      {R"({"ros2": "yes"})", "d.json:1:10: ros2: expected true or false"},
      {R"({"topics": ["a"]})", "d.json:1:12: topics: expected an object of strings"},
      {"{\"topics\": {\n    \"Base.odom\": 3}}",
       "d.json:2:18: topics: \"Base.odom\": expected a non-empty string"},
      {R"({"qos": {"depth": 0}})", "d.json:1:19: qos.depth: expected an integer from 1 to 100000"},
      {R"({"qos": {"history": 5}})",
       "d.json:1:10: qos: unknown key \"history\" (the qos keys are: depth, ports)"},
      {R"({"qos": {"dpeth": 5}})",
       "d.json:1:10: qos: unknown key \"dpeth\"; did you mean \"depth\"? (the qos keys are: "
       "depth, ports)"},
      {R"({"qos": {"ports": {"Base.odom": {"reliability": "besteffort"}}}})",
       "d.json:1:49: qos: ports: \"Base.odom\": reliability: expected \"reliable\" or "
       "\"best_effort\""},
      {R"({"qos": {"ports": {"Base.odom": {"durability": true}}}})",
       "d.json:1:48: qos: ports: \"Base.odom\": durability: expected \"volatile\" or "
       "\"transient_local\""},
      {R"({"qos": {"ports": {"Base.odom": {"reliabilty": "reliable"}}}})",
       "d.json:1:34: qos: ports: \"Base.odom\": unknown key \"reliabilty\"; did you mean "
       "\"reliability\"? (the keys are: reliability, durability)"},
      {R"({"qos": {"ports": {"Base.odom": "best_effort"}}})",
       "d.json:1:33: qos: ports: \"Base.odom\": expected an object with the keys reliability, "
       "durability"},
      {"\n  [1]", "d.json:2:3: expected a JSON object"},
      // The library would keep the last "domain" without a word: the second one is an error.
      {"{\n  \"domain\": 7,\n  \"ros2\": true,\n  \"domain\": 8\n}",
       "d.json:4:3: key \"domain\" repeated in one object (the first is at line 2); JSON "
       "readers keep only the last value, so remove one of the two"},
      {"{\"topics\": {\"Base.odom\": \"/a\",\n  \"Base.odom\": \"/b\"}}",
       "d.json:2:3: key \"Base.odom\" repeated in one object (the first is at line 1)"},
  };
  for (const Case& c : cases) {
    Deployment d;
    std::vector<Diagnostic> errors;
    EXPECT_FALSE(parse_deployment(c.text, "d.json", &d, &errors)) << c.text;
    std::string got = text_of(errors);
    EXPECT_EQ(got.rfind(c.expected, 0), 0u) << c.text << "\n  gave: " << got;
  }
}

// Every problem is reported, in the order of the file (the library hands keys over sorted),
// each with the span of its value for the caret and tildes under the quoted line.
TEST(DeploymentTest, EveryProblemInTheFilesOrder) {
  Deployment d;
  std::vector<Diagnostic> errors;
  EXPECT_FALSE(
      parse_deployment("{\"ros2\": 1,\n \"domain\": 300,\n \"bogus\": 0}", "d.json", &d, &errors));
  EXPECT_EQ(text_of(errors),
            "d.json:1:10: ros2: expected true or false\n"
            "d.json:2:12: domain: expected an integer from 0 to 232\n"
            "d.json:3:2: unknown key \"bogus\" (the keys are: domain, ros2, topics, types, qos, "
            "status; "
            "docs/distributed.md#the-deployment-file)");
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[1].loc.end_line, 2);
  EXPECT_EQ(errors[1].loc.end_column, 15);
  EXPECT_EQ(errors[1].severity, Severity::Error);
}

TEST(DeploymentTest, KeysMustNameTheAppsPortsAndTypes) {
  model::App app = two_port_app();
  struct Case {
    const char* text;
    const char* expected;
  } cases[] = {
      {"{\"topics\": {\n  \"Base.cmd\": \"/x\"}}",
       "d.json:2:3: topics: \"Base.cmd\" is not a port of app demo (write Module.port"},
      {R"({"qos": {"ports": {"Base.cmd_vell": {"reliability": "best_effort"}}}})",
       "d.json:1:20: qos: ports: \"Base.cmd_vell\" is not a port of app demo; did you mean "
       "\"Base.cmd_vel\"? (write Module.port as in the spec)"},
      {R"({"topics": {"Base.cmd_vell": "/x"}})",
       "d.json:1:13: topics: \"Base.cmd_vell\" is not a port of app demo; did you mean "
       "\"Base.cmd_vel\"? (write Module.port as in the spec)"},
      {R"({"topics": {"Base.cmd_vel": "/x", "Base.odom": "/x"}})",
       "d.json:1:48: topics: \"Base.odom\" and \"Base.cmd_vel\" are both on topic /x"},
      // Base.odom's default topic, with and without ROS 2 naming: named here, not when the
      // transport opens.
      {R"({"topics": {"Base.cmd_vel": "/Base/odom"}})",
       "d.json:1:29: topics: \"Base.cmd_vel\" is on topic Base/odom, the default topic of "
       "Base.odom; give Base.odom a topic of its own in \"topics\", or Base.cmd_vel another"},
      {R"({"topics": {"Base.cmd_vel": "/x", "Base.odom": "x"}})",
       "d.json:1:48: topics: \"Base.odom\" and \"Base.cmd_vel\" are both on topic x"},
      {R"({"ros2": true, "topics": {"Base.odom": "Base/cmd_vel"}})",
       "d.json:1:40: topics: \"Base.odom\" is on topic rt/Base/cmd_vel, the default topic of "
       "Base.cmd_vel"},
      {"{\"types\": {\"Twist\": \"a/msg/T\",\n            \"Twst\": \"a/msg/B\"}}",
       "d.json:2:13: types: \"Twst\" is not a type of app demo; did you mean \"Twist\"? (the "
       "types are: Twist, bool, float, int, string, vec3)"},
      // A status topic is about an arbitrated port's rules.
      {R"({"status": {"topics": {"Base.odom": "/odom_status"}}})",
       "d.json:1:24: status: topics: \"Base.odom\" is not an arbitrated port of app demo"},
  };
  for (const Case& c : cases) {
    Deployment d;
    std::vector<Diagnostic> errors;
    ASSERT_TRUE(parse_deployment(c.text, "d.json", &d, &errors)) << text_of(errors);
    EXPECT_FALSE(check_deployment(d, app, &errors)) << c.text;
    std::string got = text_of(errors);
    EXPECT_EQ(got.rfind(c.expected, 0), 0u) << c.text << "\n  gave: " << got;
    EXPECT_EQ(errors.size(), 1u) << got;  // one problem, said once
  }
}

// Two ports on one topic: the error is at the second, a note at the first.
TEST(DeploymentTest, ASharedTopicPointsAtBothPorts) {
  Deployment d;
  std::vector<Diagnostic> errors;
  ASSERT_TRUE(
      parse_deployment("{\"topics\": {\n  \"Base.cmd_vel\": \"/x\",\n  \"Base.odom\": \"/x\"}}",
                       "d.json", &d, &errors));
  EXPECT_FALSE(check_deployment(d, two_port_app(), &errors));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].loc.line, 3);
  ASSERT_EQ(errors[0].notes.size(), 1u);
  EXPECT_EQ(errors[0].notes[0].severity, Severity::Note);
  EXPECT_EQ(errors[0].notes[0].loc.line, 2);
  EXPECT_EQ(errors[0].notes[0].loc.column, 19);
  EXPECT_EQ(errors[0].notes[0].message, "the topic of \"Base.cmd_vel\"");
}

TEST(DeploymentTest, AMissingFileIsNamed) {
  Deployment d;
  std::vector<Diagnostic> errors;
  EXPECT_FALSE(read_deployment("/nonexistent/deploy.json", &d, &errors));
  EXPECT_EQ(text_of(errors),
            "/nonexistent/deploy.json: cannot read the deployment file (no such file)");
  // A directory is not a JSON syntax error at 1:1.
  errors.clear();
  EXPECT_FALSE(read_deployment("/", &d, &errors));
  EXPECT_EQ(text_of(errors).rfind("/: is a directory, not a deployment file", 0), 0u)
      << text_of(errors);
}

}  // namespace
}  // namespace arbc::dds
