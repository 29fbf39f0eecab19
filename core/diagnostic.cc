#include "core/diagnostic.h"

#include <fstream>
#include <sstream>

namespace arbc {

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
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

void render_into(const Diagnostic& d, SourceCache* sources, std::string& out) {
  const model::SourceLocation& loc = d.loc;
  if (!loc.file.empty()) {
    out += loc.file;
    if (loc.line > 0) out += ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column);
    out += ": ";
  }
  out += severity_name(d.severity);
  out += ": " + d.message;
  if (!d.id.empty()) out += " [" + d.id + "]";
  out += '\n';
  std::string_view text = sources ? sources->line(loc.file, loc.line) : std::string_view{};
  if (!text.empty() && loc.column >= 1) {
    out += "  ";
    out += text;
    out += "\n  ";
    // Columns count characters, not bytes: one pad per UTF-8 character (continuation bytes
    // add nothing). Keep tabs so the caret lines up under tab-indented source.
    size_t col = static_cast<size_t>(loc.column - 1);
    size_t chars = 0;
    for (size_t i = 0; chars < col && i < text.size(); ++i) {
      if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) continue;
      out += text[i] == '\t' ? '\t' : ' ';
      ++chars;
    }
    out += '^';
    if (loc.end_line == loc.line && loc.end_column > loc.column + 1) {
      size_t last = std::min(static_cast<size_t>(loc.end_column - 1), text.size());
      for (size_t i = col + 1; i < last; ++i) out += '~';
    }
    out += '\n';
  }
  for (const Diagnostic& note : d.notes) render_into(note, sources, out);
}

}  // namespace

std::string render(const Diagnostic& d, SourceCache* sources) {
  std::string out;
  render_into(d, sources, out);
  return out;
}

}  // namespace arbc
