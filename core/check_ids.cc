#include "core/check_ids.h"

namespace arbc::frontend {

namespace {

constexpr std::string_view Check = "check";
constexpr std::string_view Verify = "verify";
constexpr std::string_view Yarp = "yarp";
constexpr std::string_view Import = "import";
constexpr std::string_view Internal = "internal";

constexpr CheckId kIds[] = {
#define ARBC_DIAG(name, id, stage, meaning) {id, stage, meaning},
#include "core/check_ids.def"
#undef ARBC_DIAG
};

// The table is sorted by id, as `--list-ids` prints it and all_check_ids() promises.
constexpr bool sorted() {
  for (size_t i = 1; i < std::size(kIds); ++i)
    if (!(kIds[i - 1].id < kIds[i].id)) return false;
  return true;
}
static_assert(sorted(), "core/check_ids.def: keep the ids sorted and unique");

}  // namespace

std::span<const CheckId> all_check_ids() { return kIds; }

}  // namespace arbc::frontend
