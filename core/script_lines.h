// Where a hand-written `script` sits inside the monitor generated for it (docs/runtime.md,
// "Errors in a script"). Code generation inlines the script's text into the rule's monitor and
// opens it with one marker line naming the user's file and the number of lines inlined; the
// runtime reads the markers back, so that a run-time error on a monitor line inside the script
// cites the user's .lua file and line, not the generated monitor (which may live in a deleted
// temporary directory). One format, written and read here.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace arbc {

// "-- ---- begin specs/track.lua (12 lines; run-time errors in them cite that file)".
// `file` must not contain a newline (a Lua comment ends at one).
std::string script_begin_line(std::string_view file, size_t lines);

// The lines of a monitor that come from a user's script.
struct ScriptSpan {
  int first = 0;  // monitor line of the script's line 1
  int lines = 0;
  std::string file;
};

// Every span a monitor's text announces with script_begin_line markers.
std::vector<ScriptSpan> script_spans(std::string_view monitor_text);

// Rewrites each "CHUNK:LINE:" in `message` whose LINE falls in a span into "FILE:LINE':"
// (LINE' counted in the user's file). `chunk` is how Lua names the monitor in its messages.
std::string cite_script_lines(const std::string& message, std::string_view chunk,
                              const std::vector<ScriptSpan>& spans);

}  // namespace arbc
