// The Events table's lifetime cell. An event set by monitor code lives as long as each `set`
// says (`set e for 1s`), and only a `set` without `for` falls back to the event's declared
// lifetime (or lasts until unset); so the declaration alone would misstate the paper's
// `e_face_detected`, declared without a lifetime and always set for 1 s.
#pragma once

#include <string>

#include "core/app_model.h"

namespace arbc::docs {

// "1 s", "until unset", or, when the ways the event is set differ, each lifetime with the
// connections that give it: "1 s (track); until unset (other)". A `script` rule's lifetimes
// are its own: "as its script sets it (NAME)".
std::string event_lifetime_cell(const model::Event& event, const model::App& app);

}  // namespace arbc::docs
