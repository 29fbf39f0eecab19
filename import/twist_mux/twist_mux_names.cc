#include "import/twist_mux/twist_mux_names.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "core/spec_identifier.h"

namespace arbc::twist_mux {
namespace {

// Hands out names unique in the spec: a second `joystick` (an input and a lock may share a
// name in twist_mux) becomes `joystick_2`.
class Taken {
 public:
  std::string take(const std::string& want) {
    std::string name = want;
    for (int k = 2; !used_.insert(name).second; ++k) name = want + "_" + std::to_string(k);
    return name;
  }
  // The same for a name that brings others with it (`NAME + suffix` for each suffix): all free.
  std::string take_with(const std::string& want, const std::vector<std::string>& suffixes) {
    for (int k = 1;; ++k) {
      std::string name = k == 1 ? want : want + "_" + std::to_string(k);
      bool free = !used_.count(name);
      for (const std::string& s : suffixes) free &= !used_.count(name + s);
      if (!free) continue;
      used_.insert(name);
      for (const std::string& s : suffixes) used_.insert(name + s);
      return name;
    }
  }

 private:
  std::set<std::string> used_;
};

std::string camel(const std::string& id) {
  std::string out;
  bool up = true;
  for (char c : id) {
    if (c == '_') {
      up = true;
      continue;
    }
    out += up ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    up = false;
  }
  return out;
}

}  // namespace

MuxNames name_mux(const MuxConfig& config) {
  MuxNames n;
  Taken taken;
  n.base = taken.take("Base");
  for (const MuxEntry& e : config.inputs) {
    if (e.priority == 0) continue;  // twist_mux never publishes it (twist_mux_spec.cc warns)
    Named in;
    in.entry = &e;
    in.rule = taken.take(spec_identifier(e.name));
    in.module = taken.take(camel(in.rule));
    n.inputs.push_back(in);
  }
  std::stable_sort(n.inputs.begin(), n.inputs.end(), [](const Named& a, const Named& b) {
    return a.entry->priority > b.entry->priority;
  });
  for (const MuxEntry& e : config.locks) {
    Named l;
    l.entry = &e;
    bool blocks_some = std::any_of(n.inputs.begin(), n.inputs.end(),
                                   [&](const Named& in) { return blocks(l, in); });
    if (!blocks_some) continue;  // warned about; nothing reads it
    l.rule = spec_identifier(e.name);
    l.module = taken.take(camel(l.rule) + "Lock");
    // A lock declaration (docs/language.md#locks): its name, and the two events the front end
    // makes of it, none of them another's.
    l.event = taken.take_with(l.rule + "_lock", {"_engaged", "_heard"});
    if (e.timeout > 0) l.heard = l.event + "_heard";
    n.locks.push_back(l);
  }
  for (Named& in : n.inputs) {
    in.event = taken.take(in.rule + "_active");
    bool read = std::any_of(n.inputs.begin(), n.inputs.end(), [&](const Named& lower) {
      return lower.entry->priority < in.entry->priority;
    });
    if (read && in.entry->timeout <= 0) in.heard = taken.take(in.rule + "_heard");
  }
  return n;
}

std::vector<std::string> blocking_terms(const MuxNames& names, const Named& input) {
  std::vector<std::string> terms;
  for (const Named& above : names.inputs)
    if (above.entry->priority > input.entry->priority) {
      terms.push_back("not " + above.event);
      if (!above.heard.empty()) terms.push_back("not " + above.heard);
    }
  for (const Named& lock : names.locks)
    if (blocks(lock, input)) terms.push_back("not " + lock.event);
  return terms;
}

}  // namespace arbc::twist_mux
