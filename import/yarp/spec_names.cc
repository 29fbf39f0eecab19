#include "import/yarp/spec_names.h"

#include <map>
#include <optional>

#include "core/spec_identifier.h"
#include "import/yarp/name_scope.h"

namespace arbc::yarp {
namespace {

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

std::string identifier(const std::string& text) { return spec_identifier(text); }

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
