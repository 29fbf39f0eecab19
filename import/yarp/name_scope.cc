#include "import/yarp/name_scope.h"

namespace arbc::yarp {

std::string NameScope::give(const std::string& base, size_t owner, std::optional<size_t>* holder) {
  auto it = given_.find(base);
  if (it == given_.end()) {
    given_.emplace(base, owner);
    holder->reset();
    return base;
  }
  *holder = it->second;
  std::string name;
  for (int k = 2;; ++k) {
    name = base + "_" + std::to_string(k);
    if (!given_.count(name) && !reserved_.count(name)) break;
  }
  given_.emplace(name, owner);
  return name;
}

}  // namespace arbc::yarp
