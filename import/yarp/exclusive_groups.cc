// derive_exclusive_groups (hazards.h): a selector script that, on every path of every
// callback, unsets one of two events whenever it sets the other keeps them from being both
// present, as long as it is their only setter (YARP: a monitor unsets only its own events).
#include <algorithm>
#include <set>

#include "import/yarp/hazards.h"

namespace arbc::yarp {
namespace {

bool sets_any(const model::Connection& c, const std::string& a, const std::string& b) {
  return c.opaque || std::count(c.sets.begin(), c.sets.end(), a) ||
         std::count(c.sets.begin(), c.sets.end(), b);
}

model::SourceLocation first_set(const MonitorAnalysis& m, const std::string& event) {
  for (const MonitorCall& c : m.facts.calls) {
    if (c.function == "setEvent" && c.text == event)
      return locate(m.path, m.text, c.line, "setEvent");
  }
  return {m.path, 0, 0, 0, 0};
}

}  // namespace

void derive_exclusive_groups(YarpImport& im) {
  std::set<std::pair<std::string, std::string>> done;
  for (size_t i = 0; i < im.connections.size(); ++i) {
    const ImportedConnection& ic = im.connections[i];
    if (!ic.analysed || !ic.monitor || im.app.connections[i].opaque) continue;
    const ScriptFacts& f = ic.monitor->facts;
    if (!f.paths_ok) continue;
    for (const auto& [a, b] : f.never_both) {
      bool alone = true;
      for (size_t j = 0; j < im.app.connections.size(); ++j) {
        alone = alone && (j == i || !sets_any(im.app.connections[j], a, b));
      }
      if (!alone || !done.insert({a, b}).second) continue;
      model::ExclusiveGroup g;
      g.events = {a, b};
      g.loc = first_set(*ic.monitor, a);
      im.app.exclusive_groups.push_back(std::move(g));
    }
  }
}

}  // namespace arbc::yarp
