// arbc_yarp_receiver PORT...: opens each port, and prints every Bottle that arrives as
// "PORT<TAB>TEXT" on standard output (flushed). The portmonitor carrier and the Lua monitors of
// the connections into these ports run in this process, as they would in a module, so a test
// can watch a monitor crash the receiving process. SIGTERM ends it at once: YARP's close can
// wait for a monitor's trigger thread (setTrigInterval) for as long as its period.
#include <unistd.h>
#include <yarp/os/Bottle.h>
#include <yarp/os/BufferedPort.h>
#include <yarp/os/Network.h>
#include <yarp/os/Time.h>

#include <csignal>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace {

std::mutex g_out;

class Printer : public yarp::os::TypedReaderCallback<yarp::os::Bottle> {
 public:
  explicit Printer(std::string port) : port_(std::move(port)) {}
  using yarp::os::TypedReaderCallback<yarp::os::Bottle>::onRead;
  void onRead(yarp::os::Bottle& b) override {
    std::lock_guard<std::mutex> lock(g_out);
    std::printf("%s\t%s\n", port_.c_str(), b.toString().c_str());
    std::fflush(stdout);
  }

 private:
  std::string port_;
};

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGTERM, [](int) { _exit(0); });
  yarp::os::Network yarp;
  std::vector<std::unique_ptr<yarp::os::BufferedPort<yarp::os::Bottle>>> ports;
  std::vector<std::unique_ptr<Printer>> printers;
  for (int i = 1; i < argc; ++i) {
    auto port = std::make_unique<yarp::os::BufferedPort<yarp::os::Bottle>>();
    auto printer = std::make_unique<Printer>(argv[i]);
    port->setStrict();
    port->useCallback(*printer);
    if (!port->open(argv[i])) {
      std::fprintf(stderr, "arbc_yarp_receiver: cannot open %s\n", argv[i]);
      return 2;
    }
    ports.push_back(std::move(port));
    printers.push_back(std::move(printer));
  }
  {
    std::lock_guard<std::mutex> lock(g_out);
    std::printf("ready\n");
    std::fflush(stdout);
  }
  while (true) yarp::os::Time::delay(1.0);
}
