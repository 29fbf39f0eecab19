// Fuzzes the app.json loader. A loaded model must write back to JSON that loads again to
// the same bytes (the round trip `arbc verify app.json` relies on).
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "core/app_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string error;
  std::optional<arbc::model::App> loaded = arbc::model::from_app_json(text, &error);
  if (!loaded) {
    if (error.empty()) std::abort();
    return 0;
  }
  std::string written = arbc::model::to_app_json(*loaded);
  std::optional<arbc::model::App> again = arbc::model::from_app_json(written, &error);
  if (!again || arbc::model::to_app_json(*again) != written) std::abort();
  return 0;
}
