#include "cli/left_at_exit.h"

#include <vector>

namespace arbc::cli {

namespace {

bool ends_soon = false;

// Never destroyed: that is the point.
std::vector<std::shared_ptr<void>>& kept() {
  static auto* values = new std::vector<std::shared_ptr<void>>;
  return *values;
}

}  // namespace

void process_ends_after_command() { ends_soon = true; }

namespace detail {

bool process_ends_soon() { return ends_soon; }

void keep(std::shared_ptr<void> value) { kept().push_back(std::move(value)); }

}  // namespace detail

}  // namespace arbc::cli
