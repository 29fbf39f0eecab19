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

TEST(DeploymentTest, ReadsEveryKey) {
  Deployment d;
  std::string error;
  ASSERT_TRUE(parse_deployment(R"({"domain": 7, "ros2": true,
      "topics": {"Base.cmd_vel": "/cmd_vel"},
      "types": {"Twist": "geometry_msgs/msg/Twist"}, "qos": {"depth": 12}})",
                               "d.json", &d, &error))
      << error;
  EXPECT_EQ(d.domain, 7);
  EXPECT_TRUE(d.ros2);
  EXPECT_EQ(d.topics.at("Base.cmd_vel"), "/cmd_vel");
  EXPECT_EQ(d.types.at("Twist"), "geometry_msgs/msg/Twist");
  EXPECT_EQ(d.depth, 12);
  EXPECT_TRUE(check_deployment(d, two_port_app(), &error)) << error;
}

TEST(DeploymentTest, DefaultsWithoutKeys) {
  Deployment d;
  std::string error;
  ASSERT_TRUE(parse_deployment("{}", "d.json", &d, &error)) << error;
  EXPECT_FALSE(d.domain);
  EXPECT_FALSE(d.ros2);
  EXPECT_EQ(d.depth, kDefaultDepth);
}

// Each bad file names the file, the place and what is expected.
TEST(DeploymentTest, BadFilesSayWhatIsWrong) {
  struct Case {
    const char* text;
    const char* expected;
  } cases[] = {
      {"{\n  \"domain\": 7,\n  \"ros2\": tru\n}", "d.json:3:"},
      {R"({"domian": 7})", "d.json: domian: unknown key (the keys are: domain, ros2, topics"},
      {R"({"domain": -1})", "d.json: domain: expected an integer from 0 to 232"},
      {R"({"domain": 1.5})", "d.json: domain: expected an integer from 0 to 232"},
      {R"({"ros2": "yes"})", "d.json: ros2: expected true or false"},
      {R"({"topics": ["a"]})", "d.json: topics: expected an object of strings"},
      {R"({"topics": {"Base.odom": 3}})", "d.json: topics.Base.odom: expected a non-empty string"},
      {R"({"qos": {"depth": 0}})", "d.json: qos.depth: expected an integer from 1 to 100000"},
      {R"({"qos": {"history": 5}})", "unknown key \"history\" (the qos keys are: depth)"},
      {"[1]", "d.json: expected a JSON object"},
  };
  for (const Case& c : cases) {
    Deployment d;
    std::string error;
    EXPECT_FALSE(parse_deployment(c.text, "d.json", &d, &error)) << c.text;
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.text << "\n  gave: " << error;
  }
}

TEST(DeploymentTest, KeysMustNameTheAppsPortsAndTypes) {
  model::App app = two_port_app();
  struct Case {
    const char* text;
    const char* expected;
  } cases[] = {
      {R"({"topics": {"Base.cmd": "/x"}})", "\"Base.cmd\" is not a port of app demo"},
      {R"({"topics": {"Base.cmd_vel": "/x", "Base.odom": "/x"}})", "are both on topic /x"},
      {R"({"types": {"Twst": "a/msg/B"}})",
       "\"Twst\" is not a type of app demo (the types are: Twist, bool, float, int, string, vec3)"},
  };
  for (const Case& c : cases) {
    Deployment d;
    std::string error;
    ASSERT_TRUE(parse_deployment(c.text, "d.json", &d, &error)) << error;
    EXPECT_FALSE(check_deployment(d, app, &error)) << c.text;
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.text << "\n  gave: " << error;
  }
}

TEST(DeploymentTest, AMissingFileIsNamed) {
  Deployment d;
  std::string error;
  EXPECT_FALSE(read_deployment("/nonexistent/deploy.json", &d, &error));
  EXPECT_EQ(error, "/nonexistent/deploy.json: cannot read the deployment file");
}

}  // namespace
}  // namespace arbc::dds
