#include "lsp/text_edits.h"

#include "lsp/positions.h"

namespace arbc::lsp {

bool apply_change(std::string& text, const nlohmann::json& change, std::string* err) {
  if (!change.is_object() || !change.contains("text") || !change["text"].is_string()) {
    *err = "a content change has no text";
    return false;
  }
  const std::string& replacement = change["text"].get_ref<const std::string&>();
  auto range = change.find("range");
  if (range == change.end() || range->is_null()) {
    text = replacement;
    return true;
  }
  if (!range->is_object() || !range->contains("start") || !range->contains("end")) {
    *err = "a content change has a malformed range";
    return false;
  }
  size_t start = offset_of(text, parse_position((*range)["start"]));
  size_t end = offset_of(text, parse_position((*range)["end"]));
  if (end < start) {
    *err = "a content change's range ends before it starts";
    return false;
  }
  text.replace(start, end - start, replacement);
  return true;
}

}  // namespace arbc::lsp
