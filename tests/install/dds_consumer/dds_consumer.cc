// Reads a deployment file with the installed arbc_dds (dds/deployment.h) and prints what it
// says, or the error. usage: dds_consumer FILE
#include <cstdio>
#include <string>
#include <vector>

#include "dds/deployment.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: dds_consumer FILE\n");
    return 2;
  }
  arbc::dds::Deployment d;
  std::vector<arbc::Diagnostic> errors;
  if (!arbc::dds::read_deployment(argv[1], &d, &errors)) {
    for (const arbc::Diagnostic& e : errors) std::fputs(arbc::render(e, nullptr).c_str(), stderr);
    return 2;
  }
  std::printf("domain %d, ros2 %s, %zu topic(s), depth %d\n", d.domain.value_or(-1),
              d.ros2 ? "yes" : "no", d.topics.size(), d.depth);
  return 0;
}
