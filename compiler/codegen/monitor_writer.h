// Writes one connection's Lua monitor (docs/lowering.md#the-generated-lua): a self-contained file
// using only the PortMonitor API, with a header naming the spec, comments quoting the spec lines
// each part comes from, and the builtins it needs defined at its top.
//
// Conventions shared with the runtime (docs/runtime.md):
//   accept(msg) returns false, or false plus a drop reason ("throttled", "no-value"), or true;
//   update(msg) returns the value to deliver;
//   the constraint is not in the monitor: the runtime installs it from app.json, and sets a
//   `by priority` rule's activity event when it delivers; setEvent without a lifetime gets
//   the event's lifetime from app.json.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "compiler/lower/lowered_app.h"
#include "core/app_model.h"

namespace arbc::codegen {

// The spec's text split into lines, for quoting in comments.
class SpecLines {
 public:
  explicit SpecLines(std::string_view text);
  // Line `n` (from 1) without leading/trailing blanks, cut at 90 characters; empty if unknown.
  std::string quote(int n) const;

 private:
  std::vector<std::string_view> lines_;
};

struct MonitorText {
  std::string text;
  std::vector<model::SourceMapEntry> source_map;
};

MonitorText write_monitor(const lower::LoweredApp& app, const lower::MonitorPlan& plan,
                          const SpecLines& spec_lines);

}  // namespace arbc::codegen
