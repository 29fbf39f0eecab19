#include "compiler/codegen/target.h"

#include "compiler/codegen/embedded_target.h"
#include "compiler/codegen/yarp_target.h"

namespace arbc::codegen {

namespace {

struct Registration {
  std::string_view name;
  std::unique_ptr<Target> (*make)();
};

// Add a target here (one line) and in its own file; nothing else changes.
constexpr Registration kTargets[] = {
    {"embedded", [] { return std::unique_ptr<Target>(new EmbeddedTarget()); }},
    {"yarp", [] { return std::unique_ptr<Target>(new YarpTarget()); }},
};

}  // namespace

std::unique_ptr<Target> make_target(std::string_view name) {
  for (const Registration& r : kTargets)
    if (r.name == name) return r.make();
  return nullptr;
}

std::vector<std::string> target_names() {
  std::vector<std::string> out;
  for (const Registration& r : kTargets) out.emplace_back(r.name);
  return out;
}

}  // namespace arbc::codegen
