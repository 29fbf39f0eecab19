// Fuzzes the app.json loader. A loaded model must write back to JSON that loads again to
// the same bytes (the round trip `arbc verify app.json` relies on).
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/app_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  arbc::model::AppLoad loaded = arbc::model::from_app_json(text);
  if (!loaded.ok) {
    if (loaded.error.empty()) std::abort();
    return 0;
  }
  std::string written = arbc::model::to_app_json(loaded.app);
  arbc::model::AppLoad again = arbc::model::from_app_json(written);
  if (!again.ok || arbc::model::to_app_json(again.app) != written) std::abort();
  return 0;
}
