// Tests against real YARP (scripts/install-yarp.sh; docs/yarp.md#what-yarp-does).
//
// Each test starts its own yarpserver on a free loopback port, with its own YARP_CONFIG_HOME and
// YARP_DATA_HOME in a temporary folder, so tests run in parallel without seeing each other. The
// test writes from its own process; the destination ports live in a receiver process
// (arbc_yarp_receiver, started in the test's folder), where the portmonitor carrier and the
// Lua monitors run, as in a module: its events are fresh for each test, and a monitor that
// crashes its process does not take the test with it.
#pragma once

#include <gtest/gtest.h>
#include <yarp/os/Bottle.h>
#include <yarp/os/BufferedPort.h>
#include <yarp/os/Network.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace arbc::yarp_test {

class YarpTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // Runs the rest of the test in `folder` (monitors named by `file.NAME` are found in the
  // receiving process's working directory).
  void use_folder(const std::string& folder);
  // Makes `folder` the context CTX (found by `+context.CTX`): $YARP_DATA_HOME/contexts/CTX.
  void add_context(const std::string& name, const std::string& folder);

  // Starts the receiver process with these destination ports (once per test).
  void start_receiver(const std::vector<std::string>& ports);
  // Is the receiver still running? (A monitor can abort it.)
  bool receiver_alive();
  // What the receiver printed so far (its stdout and stderr: YARP's log, the monitors' words).
  std::string receiver_log();
  // Opens (once) a port that the test writes to.
  ::yarp::os::BufferedPort<::yarp::os::Bottle>& writer(const std::string& name);
  // Connects with a carrier string as a yarpmanager XML gives it; waits for the monitor.
  bool connect(const std::string& from, const std::string& to, const std::string& carrier);
  // Opens the ports of every <connection> of `xml` (in the current folder) and connects them.
  void connect_application(const std::string& xml);

  // Writes a Bottle given as text on the writer `port` and waits until it is sent.
  void send(const std::string& port, const std::string& text);
  // Everything the receiver's `port` received since the last call, as Bottle texts, after
  // waiting `settle` seconds for messages in flight.
  std::vector<std::string> received(const std::string& port, double settle = 0.5);

  static std::string source_dir(const std::string& relative);

 private:
  std::map<std::string, std::unique_ptr<::yarp::os::BufferedPort<::yarp::os::Bottle>>> writers_;
  std::map<std::string, std::vector<std::string>> pending_;  // read from the receiver, not taken
  size_t read_offset_ = 0;
  bool owns_ = false;  // this test started the server
};

}  // namespace arbc::yarp_test
