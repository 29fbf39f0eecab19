#include "import/yarp/spec_names.h"

#include <cctype>
#include <map>
#include <optional>

#include "import/yarp/name_scope.h"

namespace arbc::yarp {
namespace {

constexpr const char* kSpecKeywords[] = {
    "app",    "type",     "const",     "module", "in",        "out",       "event",
    "events", "from",     "lifetime",  "for",    "exclusive", "invariant", "arbitrate",
    "by",     "priority", "complete",  "when",   "hold",      "connect",   "assert",
    "let",    "var",      "accept",    "set",    "unset",     "if",        "else",
    "emit",   "throttle", "every",     "script", "not",       "and",       "or",
    "true",   "false",    "otherwise", "never",  "two",       "within",    "while",
    "only",   "after",    "assume",    "until",  "stops",     "given",     "stable"};

bool is_keyword(const std::string& s) {
  for (const char* k : kSpecKeywords) {
    if (s == k) return true;
  }
  return false;
}

// Where a connection's rule name comes from, for the warning: its id, or the name arbc made.
std::string origin(const XmlConnection& x, const std::string& model_name) {
  return x.id.empty() ? "the rule arbc named '" + model_name + "'" : "id '" + x.id + "'";
}

Diagnostic renamed_warning(const YarpImport& im, size_t first, size_t later,
                           const std::string& shared, const std::string& name) {
  const XmlConnection& a = im.connections[first].xml;
  const XmlConnection& b = im.connections[later].xml;
  Diagnostic d;
  d.severity = Severity::Warning;
  d.loc = b.id_loc;
  d.id = kIdSpecName;
  d.message = "connection " + origin(b, im.app.connections[later].name) + " into " + b.to +
              " becomes the spec name '" + shared + "', as does " +
              origin(a, im.app.connections[first].name) + " of the connection at line " +
              std::to_string(a.loc.line) + ": this connection's rule in the imported spec is '" +
              name + "'";
  d.notes.push_back(
      {Severity::Note, a.id_loc, "that connection's rule is '" + shared + "'", "", {}});
  d.notes.push_back({Severity::Note,
                     {},
                     "spec names hold letters, digits and '_' only: give the connections ids "
                     "that differ in those",
                     "",
                     {}});
  return d;
}

}  // namespace

std::string identifier(const std::string& text) {
  std::string out;
  for (char c : text) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  while (!out.empty() && out.front() == '_') out.erase(out.begin());
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "p_" + out;
  if (is_keyword(out)) out += "_";
  return out;
}

std::vector<std::string> spec_rule_names(const YarpImport& im, std::vector<Diagnostic>& renamed) {
  const std::vector<model::Connection>& conns = im.app.connections;
  std::vector<std::string> names(conns.size());
  std::map<std::string, NameScope> ports;  // by destination port
  for (const model::Connection& c : conns) ports[c.destination].reserve(identifier(c.name));
  for (size_t i = 0; i < conns.size(); ++i) {
    std::string base = identifier(conns[i].name);
    std::optional<size_t> holder;
    names[i] = ports[conns[i].destination].give(base, i, &holder);
    if (holder) renamed.push_back(renamed_warning(im, *holder, i, base, names[i]));
  }
  return names;
}

}  // namespace arbc::yarp
