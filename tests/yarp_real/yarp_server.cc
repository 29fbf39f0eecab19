#include "tests/yarp_real/yarp_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <random>
#include <thread>

extern char** environ;

namespace arbc::yarp_test {
namespace {

bool can_bind(int port) {
  int s = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  a.sin_port = htons(static_cast<uint16_t>(port));
  bool ok = bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  close(s);
  return ok;
}

}  // namespace

// Blocks lie below the kernel's ephemeral range (32768 and up): a port that cannot bind its
// number fails to open.
int reserve_port_block() {
  std::mt19937 rng(
      static_cast<unsigned>(getpid()) ^
      static_cast<unsigned>(std::chrono::steady_clock::now().time_since_epoch().count()));
  for (int attempt = 0; attempt < 400; ++attempt) {
    int base = 10000 + 100 * static_cast<int>(rng() % 220);
    std::string lock = "/tmp/arbc-yarp-ports-" + std::to_string(base) + ".lock";
    int fd = open(lock.c_str(), O_CREAT | O_RDWR, 0666);
    if (fd < 0) continue;
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      close(fd);
      continue;
    }
    bool free = true;
    for (int p = base; p < base + 50 && free; ++p) free = can_bind(p);
    if (free) return base;
    close(fd);
  }
  return -1;
}

pid_t start_yarpserver(const std::string& yarpserver, int port, const std::string& log) {
  std::string port_text = std::to_string(port);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  const char* argv[] = {yarpserver.c_str(), "--read",          "--ip", "127.0.0.1",
                        "--socket",         port_text.c_str(), nullptr};
  pid_t pid = -1;
  int rc =
      posix_spawn(&pid, yarpserver.c_str(), &actions, nullptr, const_cast<char**>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

void stop_process(pid_t& pid) {
  if (pid <= 0) return;
  kill(pid, SIGTERM);
  int status = 0;
  pid_t done = 0;
  for (int i = 0; i < 50 && (done = waitpid(pid, &status, WNOHANG)) == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (done == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
  pid = -1;
}

}  // namespace arbc::yarp_test
