#include "compiler/codegen/yarp_filled_modules.h"

#include <algorithm>
#include <cctype>
#include <optional>

namespace arbc::codegen {

namespace {

struct Span {
  size_t begin = 0, end = 0;  // [begin, end) of a <module>...</module> element
};

// The <module> element right after arbc's comment for spec module `name` in `text`.
std::optional<Span> module_after_comment(const std::string& text, const std::string& name) {
  std::string marker = "<!-- " + name;
  for (size_t at = text.find(marker); at != std::string::npos; at = text.find(marker, at + 1)) {
    size_t after = at + marker.size();
    if (after >= text.size() || (text[after] != ':' && text[after] != '.')) continue;
    size_t close = text.find("-->", after);
    if (close == std::string::npos) return std::nullopt;
    size_t begin = close + 3;
    while (begin < text.size() && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    if (text.compare(begin, 8, "<module>") != 0) return std::nullopt;
    size_t end = text.find("</module>", begin);
    if (end == std::string::npos) return std::nullopt;
    return Span{begin, end + 9};
  }
  return std::nullopt;
}

// The spec module of the placeholder at `begin` of `text`: the text of its <name>.
std::string placeholder_name(const std::string& text, const Span& s) {
  size_t open = text.find("<name>", s.begin);
  size_t close = text.find("</name>", open);
  if (open == std::string::npos || close == std::string::npos || close > s.end) return "";
  return text.substr(open + 6, close - open - 6);
}

// The placeholder arbc writes for spec module `name`.
std::string placeholder_for(const std::string& name) {
  return "<module>\n    <name>" + name +
         "</name>\n    <parameters></parameters>\n    <node>localhost</node>\n  </module>";
}

// The modules of `previous` filled in by the user (arbc's comment, then a <module> that is not
// its placeholder), by spec module name.
std::vector<std::string> filled_in(const std::string& previous) {
  std::vector<std::string> out;
  for (size_t at = previous.find("<!-- "); at != std::string::npos;
       at = previous.find("<!-- ", at + 1)) {
    size_t begin = at + 5, end = begin;
    while (end < previous.size() &&
           (std::isalnum(static_cast<unsigned char>(previous[end])) || previous[end] == '_'))
      ++end;
    if (end == begin) continue;
    std::string name = previous.substr(begin, end - begin);
    std::optional<Span> user = module_after_comment(previous, name);
    if (user && previous.compare(user->begin, user->end - user->begin, placeholder_for(name)) != 0)
      out.push_back(name);
  }
  return out;
}

}  // namespace

std::string keep_filled_modules(const std::string& generated, const std::string& previous,
                                std::vector<std::string>* kept, std::vector<std::string>* dropped) {
  std::string out;
  size_t from = 0;
  for (size_t at = generated.find("<module>"); at != std::string::npos;
       at = generated.find("<module>", at + 1)) {
    size_t end = generated.find("</module>", at);
    if (end == std::string::npos) break;
    Span placeholder{at, end + 9};
    std::string name = placeholder_name(generated, placeholder);
    std::optional<Span> user = module_after_comment(previous, name);
    std::string placeholder_text = generated.substr(at, placeholder.end - at);
    if (name.empty() || !user) continue;
    std::string user_text = previous.substr(user->begin, user->end - user->begin);
    if (user_text == placeholder_text) continue;
    out += generated.substr(from, at - from) + user_text;
    from = placeholder.end;
    kept->push_back(name);
  }
  for (const std::string& name : filled_in(previous)) {
    if (std::find(kept->begin(), kept->end(), name) == kept->end() &&
        std::find(dropped->begin(), dropped->end(), name) == dropped->end())
      dropped->push_back(name);
  }
  return out + generated.substr(from);
}

}  // namespace arbc::codegen
