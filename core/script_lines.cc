#include "core/script_lines.h"

#include <algorithm>
#include <charconv>

namespace arbc {

namespace {

constexpr std::string_view kBegin = "-- ---- begin ";
constexpr std::string_view kEnd = " lines; run-time errors in them cite that file)";

// Parses one marker line (the generator may indent it); nullopt when `line` is not one.
std::optional<ScriptSpan> parse_marker(std::string_view line) {
  line.remove_prefix(std::min(line.size(), line.find_first_not_of(" \t")));  // indentation
  if (line.substr(0, kBegin.size()) != kBegin || line.size() < kBegin.size() + kEnd.size() ||
      line.substr(line.size() - kEnd.size()) != kEnd)
    return std::nullopt;
  std::string_view body = line.substr(kBegin.size(), line.size() - kBegin.size() - kEnd.size());
  size_t open = body.rfind(" (");
  if (open == std::string_view::npos) return std::nullopt;
  ScriptSpan span;
  std::string_view count = body.substr(open + 2);
  auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), span.lines);
  if (ec != std::errc() || end != count.data() + count.size()) return std::nullopt;
  span.file = std::string(body.substr(0, open));
  return span;
}

}  // namespace

std::string script_begin_line(std::string_view file, size_t lines) {
  return std::string(kBegin) + std::string(file) + " (" + std::to_string(lines) + std::string(kEnd);
}

std::vector<ScriptSpan> script_spans(std::string_view monitor_text) {
  std::vector<ScriptSpan> spans;
  int number = 1;
  for (size_t start = 0; start < monitor_text.size(); ++number) {
    size_t end = monitor_text.find('\n', start);
    if (end == std::string_view::npos) end = monitor_text.size();
    if (auto span = parse_marker(monitor_text.substr(start, end - start))) {
      span->first = number + 1;
      spans.push_back(std::move(*span));
    }
    start = end + 1;
  }
  return spans;
}

std::string cite_script_lines(const std::string& message, std::string_view chunk,
                              const std::vector<ScriptSpan>& spans) {
  if (spans.empty() || chunk.empty()) return message;
  std::string out;
  size_t at = 0;
  for (size_t hit; (hit = message.find(chunk, at)) != std::string::npos;) {
    size_t digits = hit + chunk.size() + 1;
    size_t stop = digits;
    while (stop < message.size() && message[stop] >= '0' && message[stop] <= '9') ++stop;
    int line = 0;
    bool located =
        digits <= message.size() && message[digits - 1] == ':' && stop > digits &&
        stop < message.size() && message[stop] == ':' &&
        std::from_chars(message.data() + digits, message.data() + stop, line).ec == std::errc();
    const ScriptSpan* span = nullptr;
    for (const ScriptSpan& s : spans)
      if (located && line >= s.first && line < s.first + s.lines) span = &s;
    out.append(message, at, hit - at);
    if (span) {
      out += span->file + ":" + std::to_string(line - span->first + 1);
      at = stop;
    } else {
      out.append(chunk);
      at = hit + chunk.size();
    }
  }
  out.append(message, at, std::string::npos);
  return out;
}

}  // namespace arbc
