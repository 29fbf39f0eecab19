#include "tests/yarp_real/yarp_fixture.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yarp/os/Time.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "import/yarp/app_xml.h"
#include "tests/support/tree_paths.h"
#include "tests/yarp_real/yarp_server.h"

extern char** environ;

namespace arbc::yarp_test {
namespace {

namespace fs = std::filesystem;

pid_t g_server = -1;
pid_t g_receiver = -1;
fs::path g_tmp;
fs::path g_start_dir;

}  // namespace

void YarpTest::SetUp() {
  owns_ = true;
  g_start_dir = fs::current_path();
  char pattern[] = "/tmp/arbc-yarp-XXXXXX";
  ASSERT_NE(mkdtemp(pattern), nullptr);
  g_tmp = pattern;
  fs::create_directories(g_tmp / "conf");
  fs::create_directories(g_tmp / "data" / "contexts");
  setenv("YARP_CONFIG_HOME", (g_tmp / "conf").c_str(), 1);
  setenv("YARP_DATA_HOME", (g_tmp / "data").c_str(), 1);
  setenv("YARP_DATA_DIRS", ARBC_YARP_PREFIX "/share/yarp", 1);
  setenv("LUA_CPATH", ARBC_YARP_PREFIX "/lib/lua/5.4/?.so;;", 1);
  int port = reserve_port_block();
  ASSERT_GT(port, 0) << "no free block of ports between 10000 and 32000";
  std::ofstream(g_tmp / "conf" / "yarp.conf") << "127.0.0.1 " << port << " yarp\n";
  g_server = start_yarpserver(ARBC_YARPSERVER, port, (g_tmp / "yarpserver.log").string());
  ASSERT_GT(g_server, 0) << "cannot start " << ARBC_YARPSERVER;
  ::yarp::os::Network::init();
  bool up = false;
  for (int i = 0; i < 100 && !up; ++i) {  // the server takes a moment to listen
    up = ::yarp::os::Network::checkNetwork(0.5);
    if (!up) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_TRUE(up) << "yarpserver did not come up; see " << (g_tmp / "yarpserver.log");
}

void YarpTest::TearDown() {
  if (!owns_) return;
  stop_process(g_receiver);
  for (auto& [name, port] : writers_) port->close();
  writers_.clear();
  ::yarp::os::Network::fini();
  stop_process(g_server);
  std::error_code ec;
  fs::current_path(g_start_dir, ec);
  fs::remove_all(g_tmp, ec);
}

std::string YarpTest::source_dir(const std::string& relative) {
  return (fs::path(arbc::testing::source_dir()) / relative).string();
}

void YarpTest::use_folder(const std::string& folder) { fs::current_path(folder); }

void YarpTest::add_context(const std::string& name, const std::string& folder) {
  fs::create_directory_symlink(folder, g_tmp / "data" / "contexts" / name);
}

::yarp::os::BufferedPort<::yarp::os::Bottle>& YarpTest::writer(const std::string& name) {
  auto& p = writers_[name];
  if (!p) {
    p = std::make_unique<::yarp::os::BufferedPort<::yarp::os::Bottle>>();
    EXPECT_TRUE(p->open(name)) << name;
  }
  return *p;
}

void YarpTest::start_receiver(const std::vector<std::string>& ports) {
  ASSERT_LE(g_receiver, 0) << "one receiver per test";
  std::string out = (g_tmp / "received.txt").string();
  std::vector<const char*> argv{ARBC_YARP_RECEIVER};
  for (const std::string& p : ports) argv.push_back(p.c_str());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::string log = (g_tmp / "receiver.log").string();
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  int rc = posix_spawn(&g_receiver, ARBC_YARP_RECEIVER, &actions, nullptr,
                       const_cast<char**>(argv.data()), environ);
  posix_spawn_file_actions_destroy(&actions);
  ASSERT_EQ(rc, 0) << "cannot start " << ARBC_YARP_RECEIVER;
  for (const std::string& p : ports) {
    bool there = false;
    for (int i = 0; i < 100 && !there; ++i) {
      there = ::yarp::os::Network::exists(p, true);
      if (!there) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ASSERT_TRUE(there) << p << " did not open; see " << log;
  }
}

std::string YarpTest::receiver_log() {
  std::ifstream in(g_tmp / "receiver.log", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool YarpTest::receiver_alive() {
  int status = 0;
  return g_receiver > 0 && waitpid(g_receiver, &status, WNOHANG) == 0;
}

bool YarpTest::connect(const std::string& from, const std::string& to, const std::string& carrier) {
  bool ok = ::yarp::os::Network::connect(from, to, carrier.empty() ? "tcp" : carrier);
  ::yarp::os::Time::delay(0.2);  // the receiving side loads the monitor and runs create
  return ok;
}

void YarpTest::connect_application(const std::string& xml) {
  std::vector<Diagnostic> diags;
  std::optional<arbc::yarp::XmlApplication> app = arbc::yarp::read_application_xml(xml, diags);
  ASSERT_TRUE(app) << xml;
  std::vector<std::string> destinations;
  for (const arbc::yarp::XmlConnection& c : app->connections) {
    writer(c.from);
    if (std::find(destinations.begin(), destinations.end(), c.to) == destinations.end())
      destinations.push_back(c.to);
  }
  start_receiver(destinations);
  for (const arbc::yarp::XmlConnection& c : app->connections) {
    EXPECT_TRUE(connect(c.from, c.to, c.protocol)) << c.from << " -> " << c.to;
  }
}

void YarpTest::send(const std::string& port, const std::string& text) {
  ::yarp::os::BufferedPort<::yarp::os::Bottle>& p = writer(port);
  ::yarp::os::Bottle& b = p.prepare();
  b.fromString(text);
  p.writeStrict();
  p.waitForWrite();
  ::yarp::os::Time::delay(0.2);  // the receiver handles each connection in its own thread
}

std::vector<std::string> YarpTest::received(const std::string& port, double settle) {
  ::yarp::os::Time::delay(settle);
  std::ifstream in(g_tmp / "received.txt", std::ios::binary);
  in.seekg(static_cast<std::streamoff>(read_offset_));
  std::string line;
  while (std::getline(in, line)) {
    if (in.eof()) break;  // a line still being written
    read_offset_ += line.size() + 1;
    size_t tab = line.find('\t');
    if (tab != std::string::npos) pending_[line.substr(0, tab)].push_back(line.substr(tab + 1));
  }
  std::vector<std::string> out = std::move(pending_[port]);
  pending_.erase(port);
  return out;
}

}  // namespace arbc::yarp_test
