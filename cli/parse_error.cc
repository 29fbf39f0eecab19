#include "cli/parse_error.h"

#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/suggest.h"

namespace arbc::cli {

namespace {

// The one unknown option among the extras of an ExtrasError ("The following arguments were not
// expected: 3 --seeed": the option's value comes along), or "" when there is none or several.
std::string the_unknown_option(const CLI::ParseError& e) {
  if (!dynamic_cast<const CLI::ExtrasError*>(&e)) return "";
  std::string message = e.what();
  size_t colon = message.find(": ");
  if (colon == std::string::npos) return "";
  std::string found;
  size_t at = colon + 2;
  while (at < message.size()) {
    size_t end = message.find(' ', at);
    if (end == std::string::npos) end = message.size();
    std::string word = message.substr(at, end - at);
    if (word.rfind("--", 0) == 0) {
      if (!found.empty()) return "";
      found = word.substr(0, word.find('='));
    }
    at = end + 1;
  }
  return found;
}

}  // namespace

int exit_for_parse_error(CLI::App& app, const CLI::ParseError& e) {
  std::string unknown = the_unknown_option(e);
  std::vector<std::string> options;
  for (const CLI::Option* o : app.get_options())
    for (const std::string& name : o->get_lnames()) options.push_back("--" + name);
  auto meant = unknown.empty() ? std::nullopt : closest_name(unknown, options);
  if (!meant) return app.exit(e) == 0 ? kExitOk : kExitBadInput;
  std::fprintf(stderr,
               "%s: there is no option %s: did you mean '%s'?\nRun with --help for more "
               "information.\n",
               app.get_name().c_str(), unknown.c_str(), meant->c_str());
  return kExitBadInput;
}

}  // namespace arbc::cli
