// One YARP hop, direct and arbitrated (bench/figures/yarp.sh prints the figures).
//
//   yarp_hop_bench ROUNDS PINGS      the driver: prints "direct US" and "arbitrated US" lines,
//                                    one per round, each the median one-way time of PINGS
//                                    round trips halved
//   yarp_hop_bench --echo            the echo process the driver starts
//
// The driver starts a private yarpserver and an echo process; /bench/ping:o -> /bench/echo:i,
// the echo writes back on /bench/echo:o -> /bench/pong:i. Direct: both legs plain tcp.
// Arbitrated: both legs through the portmonitor carrier with a Lua monitor whose constraint
// reads an event, beside a second, idle connection into the same port whose constraint is the
// negation (an arbitrated port as `arbc build --target yarp` writes it), so each leg is one
// arbitrated hop and half the round trip is the figure. Modes alternate round by round so the
// machine's load falls on both alike.
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yarp/os/Bottle.h>
#include <yarp/os/BufferedPort.h>
#include <yarp/os/Network.h>
#include <yarp/os/Time.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/yarp_real/yarp_server.h"

namespace {

namespace fs = std::filesystem;
using Port = yarp::os::BufferedPort<yarp::os::Bottle>;

// What the connections of an arbitrated port run (written into the working folder, where
// the receiving processes look for `file.NAME`).
const char* kSelectedMonitor = R"(require("yarp")
PortMonitor.create = function(options)
  PortMonitor.setConstraint("e_go")
  PortMonitor.setEvent("e_go")
  return true
end
PortMonitor.accept = function(thing)
  return thing:asBottle():size() > 0
end
)";
const char* kIdleMonitor = R"(require("yarp")
PortMonitor.create = function(options)
  PortMonitor.setConstraint("not e_go")
  return true
end
)";

const std::string kArbitrated = "tcp+recv.portmonitor+type.lua+file.";

// Echoes every Bottle from /bench/echo:i to /bench/echo:o; opens the idle source of pong:i.
int run_echo() {
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the driver
  yarp::os::Network yarp;
  Port in, out, idle;
  if (!in.open("/bench/echo:i") || !out.open("/bench/echo:o") || !idle.open("/bench/idle_b:o"))
    return 2;
  in.setStrict();
  while (true) {
    yarp::os::Bottle* b = in.read(true);
    if (b == nullptr) continue;
    out.prepare() = *b;
    out.writeStrict();
  }
}

pid_t start_echo(const char* self) {
  pid_t pid = fork();
  if (pid == 0) {
    execl(self, self, "--echo", static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

bool wait_for(const std::string& port) {
  for (int i = 0; i < 200; ++i) {
    if (yarp::os::Network::exists(port, true)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

void disconnect_all() {
  yarp::os::Network::disconnect("/bench/ping:o", "/bench/echo:i", true);
  yarp::os::Network::disconnect("/bench/idle_a:o", "/bench/echo:i", true);
  yarp::os::Network::disconnect("/bench/echo:o", "/bench/pong:i", true);
  yarp::os::Network::disconnect("/bench/idle_b:o", "/bench/pong:i", true);
}

// Wires both legs for a mode; false if YARP refuses a connection.
bool wire(bool arbitrated) {
  disconnect_all();
  std::string selected = arbitrated ? kArbitrated + "bench_selected" : "tcp";
  bool ok = yarp::os::Network::connect("/bench/ping:o", "/bench/echo:i", selected, true) &&
            yarp::os::Network::connect("/bench/echo:o", "/bench/pong:i", selected, true);
  if (arbitrated) {
    std::string idle = kArbitrated + "bench_idle";
    ok = ok && yarp::os::Network::connect("/bench/idle_a:o", "/bench/echo:i", idle, true) &&
         yarp::os::Network::connect("/bench/idle_b:o", "/bench/pong:i", idle, true);
  }
  yarp::os::Time::delay(0.3);  // the receiving sides load the monitors and run create
  return ok;
}

// Median one-way time in microseconds over `pings` round trips (after a warm-up).
double measure(Port& ping, Port& pong, int pings) {
  std::vector<double> one_way;
  for (int i = -pings / 10; i < pings; ++i) {
    yarp::os::Bottle& b = ping.prepare();
    b.clear();
    b.addInt64(i);
    b.addFloat64(0.5);
    b.addString("payload");
    auto start = std::chrono::steady_clock::now();
    ping.writeStrict();
    yarp::os::Bottle* reply = pong.read(true);
    auto end = std::chrono::steady_clock::now();
    if (reply == nullptr || reply->get(0).asInt64() != i) {
      std::fprintf(stderr, "yarp_hop_bench: ping %d came back wrong or not at all\n", i);
      std::exit(3);
    }
    if (i >= 0)
      one_way.push_back(std::chrono::duration<double, std::micro>(end - start).count() / 2);
  }
  std::nth_element(one_way.begin(), one_way.begin() + one_way.size() / 2, one_way.end());
  return one_way[one_way.size() / 2];
}

// A private name server in a temporary folder, so the benchmark never meets other YARP users.
bool start_private_network(const fs::path& folder, pid_t* server) {
  fs::create_directories(folder / "conf");
  setenv("YARP_CONFIG_HOME", (folder / "conf").c_str(), 1);
  setenv("YARP_DATA_HOME", folder.c_str(), 1);
  setenv("YARP_DATA_DIRS", ARBC_YARP_PREFIX "/share/yarp", 1);  // the portmonitor carrier
  setenv("LUA_CPATH", ARBC_YARP_PREFIX "/lib/lua/5.4/?.so;;", 1);
  int port = arbc::yarp_test::reserve_port_block();
  if (port < 0) return false;
  std::ofstream(folder / "conf" / "yarp.conf") << "127.0.0.1 " << port << " yarp\n";
  *server = arbc::yarp_test::start_yarpserver(ARBC_YARPSERVER, port,
                                              (folder / "yarpserver.log").string());
  return *server > 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--echo") return run_echo();
  if (argc != 3) {
    std::fprintf(stderr, "usage: yarp_hop_bench ROUNDS PINGS\n");
    return 2;
  }
  int rounds = std::atoi(argv[1]), pings = std::atoi(argv[2]);
  if (rounds < 1 || pings < 10) {
    std::fprintf(stderr, "yarp_hop_bench: ROUNDS >= 1 and PINGS >= 10\n");
    return 2;
  }
  std::signal(SIGALRM, [](int) {
    const char text[] = "yarp_hop_bench: no progress for 120 s (a message was lost)\n";
    (void)!write(2, text, sizeof text - 1);
    _exit(3);
  });
  char folder_pattern[] = "/tmp/arbc-yarp-bench-XXXXXX";
  fs::path folder = mkdtemp(folder_pattern);
  fs::current_path(folder);
  std::ofstream("bench_selected.lua") << kSelectedMonitor;
  std::ofstream("bench_idle.lua") << kIdleMonitor;
  pid_t server = -1, echo = -1;
  int status = 1;
  if (start_private_network(folder, &server)) {
    yarp::os::Network yarp;
    for (int i = 0; i < 100 && !yarp::os::Network::checkNetwork(0.5); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    Port ping, pong, idle;
    echo = start_echo("/proc/self/exe");
    if (ping.open("/bench/ping:o") && pong.open("/bench/pong:i") && idle.open("/bench/idle_a:o") &&
        wait_for("/bench/echo:o") && wait_for("/bench/idle_b:o")) {
      pong.setStrict();
      status = 0;
      for (int r = 0; r < rounds && status == 0; ++r) {
        for (bool arbitrated : {false, true}) {
          alarm(120);  // a lost message must not hang the benchmark run
          if (!wire(arbitrated)) {
            std::fprintf(stderr, "yarp_hop_bench: a connection was refused\n");
            status = 3;
            break;
          }
          std::printf("%s %.1f\n", arbitrated ? "arbitrated" : "direct",
                      measure(ping, pong, pings));
          std::fflush(stdout);
        }
      }
      disconnect_all();
    } else {
      std::fprintf(stderr, "yarp_hop_bench: the ports did not open (see %s)\n", folder.c_str());
    }
    arbc::yarp_test::stop_process(echo);
  } else {
    std::fprintf(stderr, "yarp_hop_bench: cannot start a yarpserver\n");
  }
  arbc::yarp_test::stop_process(server);
  std::error_code ec;
  fs::remove_all(folder, ec);
  return status;
}
