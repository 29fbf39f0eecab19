#include "core/diagnostic.h"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace arbc {

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::Error:
      return "error";
    case Severity::Warning:
      return "warning";
    case Severity::Note:
      return "note";
  }
  return "error";
}

void SourceCache::add(std::string file, std::string text) {
  Text t;
  t.content = std::move(text);
  t.line_starts.push_back(0);
  for (size_t i = 0; i < t.content.size(); ++i)
    if (t.content[i] == '\n') t.line_starts.push_back(i + 1);
  texts_[std::move(file)] = std::move(t);
}

SourceCache::Text& SourceCache::load(const std::string& file) {
  auto it = texts_.find(file);
  if (it != texts_.end()) return it->second;
  std::ifstream in(file, std::ios::binary);
  std::ostringstream buffer;
  if (in) buffer << in.rdbuf();
  add(file, buffer.str());
  return texts_[file];
}

std::string_view SourceCache::line(const std::string& file, int line) {
  if (file.empty() || line < 1) return {};
  Text& t = load(file);
  if (static_cast<size_t>(line) > t.line_starts.size()) return {};
  size_t start = t.line_starts[line - 1];
  size_t end = t.content.find('\n', start);
  if (end == std::string::npos) end = t.content.size();
  if (end > start && t.content[end - 1] == '\r') --end;
  return std::string_view(t.content).substr(start, end - start);
}

namespace {

constexpr size_t kQuoteWidth = 200;  // cells of a long source line shown around the caret

bool is_control(unsigned char c) { return (c < 0x20 && c != '\t') || c == 0x7F; }

std::string escaped(unsigned char c) {
  static const char* kHex = "0123456789ABCDEF";
  return std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
}

// Text that may come from the user's file, with control characters (a terminal's escape
// sequences, a carriage return) shown as \xNN so that they cannot repaint the terminal.
std::string printable(std::string_view text) {
  std::string out;
  for (char ch : text) {
    unsigned char c = static_cast<unsigned char>(ch);
    out += is_control(c) && c != '\n' ? escaped(c) : std::string(1, ch);
  }
  return out;
}

// One character of a source line as shown: UTF-8 sequences whole, control characters escaped.
struct Shown {
  std::string text;
  size_t cells = 1;  // columns it takes on the terminal (a tab: one, kept as a tab)
};

std::vector<Shown> shown_characters(std::string_view line) {
  std::vector<Shown> chars;
  for (size_t i = 0; i < line.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(line[i]);
    if ((c & 0xC0) == 0x80 && !chars.empty()) {  // continuation byte: part of the previous
      chars.back().text += line[i];
    } else if (is_control(c)) {
      chars.push_back({escaped(c), 4});
    } else {
      chars.push_back({std::string(1, line[i]), 1});
    }
  }
  return chars;
}

// Quotes `text` with a caret (and tildes) under the located columns. Columns count
// characters. A line wider than kQuoteWidth is cut around the caret, with "..." at each cut.
void quote_line(std::string_view text, const model::SourceLocation& loc, std::string& out) {
  std::vector<Shown> chars = shown_characters(text);
  size_t caret = std::min(static_cast<size_t>(loc.column - 1), chars.size());
  size_t tilde_end = caret + 1;
  if (loc.end_line == loc.line && loc.end_column > loc.column + 1)
    tilde_end = std::min(static_cast<size_t>(loc.end_column - 1), chars.size());
  size_t first = 0, last = chars.size(), cells = 0;
  for (const Shown& ch : chars) cells += ch.cells;
  if (cells > kQuoteWidth) {
    size_t left = 0;  // cells kept left of the caret: about half the width
    first = caret;
    while (first > 0 && left + chars[first - 1].cells <= kQuoteWidth / 2)
      left += chars[--first].cells;
    last = first;
    for (size_t used = 0; last < chars.size() && used + chars[last].cells <= kQuoteWidth;)
      used += chars[last++].cells;
  }
  out += first > 0 ? "  ..." : "  ";
  for (size_t i = first; i < last; ++i) out += chars[i].text;
  out += last < chars.size() ? "..." : "";
  out += first > 0 ? "\n     " : "\n  ";
  for (size_t i = first; i < caret && i < last; ++i)
    out += chars[i].text == "\t" ? std::string("\t") : std::string(chars[i].cells, ' ');
  out += '^';
  for (size_t i = caret + 1; i < tilde_end && i < last; ++i)
    out += std::string(chars[i].cells, '~');
  out += '\n';
}

void render_into(const Diagnostic& d, SourceCache* sources, std::string& out) {
  const model::SourceLocation& loc = d.loc;
  if (!loc.file.empty()) {
    out += printable(loc.file.str());
    if (loc.line > 0) out += ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column);
    out += ": ";
  }
  out += severity_name(d.severity);
  out += ": " + printable(d.message);
  if (!d.id.empty()) out += " [" + d.id + "]";
  out += '\n';
  std::string_view text = sources ? sources->line(loc.file, loc.line) : std::string_view{};
  if (!text.empty() && loc.column >= 1) quote_line(text, loc, out);
  for (const Diagnostic& note : d.notes) render_into(note, sources, out);
}

}  // namespace

std::string render(const Diagnostic& d, SourceCache* sources) {
  std::string out;
  render_into(d, sources, out);
  return out;
}

}  // namespace arbc
