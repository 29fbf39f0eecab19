// The names a YARP deployment of a spec uses (docs/yarp.md#names-on-yarp): YARP port names,
// one YARP connection per (source port, destination port) pair, the monitor file of each, and
// the YARP event names. YARP evaluates a constraint by replacing event names as substrings of
// its text and keeps events in one table per process, so every (arbitrated port, event, owner)
// gets its own name `E<nn>_<port>__<event>`: the only capital letter is the leading E and the
// number has one width, so no name is part of another or of a Lua keyword.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::codegen {

// The connections of the spec that share one (source, destination) pair: YARP allows one
// connection per pair, so they become one YARP connection with one monitor.
struct YarpLink {
  std::string source, destination;   // spec ports "Module.port"
  std::vector<size_t> parts;         // indexes into App::connections, in model order
  std::string id;                    // the XML connection id: the delivering rule's name
  std::string monitor;               // file name without ".lua"; empty: a plain tcp connection
  std::optional<size_t> delivering;  // the part that may deliver (rule or connect), if any
};

class YarpNames {
 public:
  // `ports`: deployment overrides "Module.port" -> "/name" (already checked).
  YarpNames(const model::App& app, std::map<std::string, std::string> ports);

  // The YARP port name of a spec port: the override, else /Module/port:o or /Module/port:i.
  std::string port(const std::string& qualified) const;
  const std::vector<YarpLink>& links() const { return links_; }
  // The YARP name of `event` in `port`'s container as connection `owner` sets it; empty when
  // `owner` never sets it there.
  std::string event(const std::string& port, const std::string& event,
                    const std::string& owner) const;
  // Every YARP name of `event` in `port` (one per owner), in model order; none: never present.
  std::vector<std::string> owners_of(const std::string& port, const std::string& event) const;
  // Every YARP event name: name -> (port, event, owner), for the port map.
  struct EventKey {
    std::string port, event, owner;
  };
  const std::map<std::string, EventKey>& all_events() const { return events_; }

 private:
  void make_links(const model::App& app);
  void make_events(const model::App& app);

  std::map<std::string, std::string> ports_;
  const model::App& app_;
  std::vector<YarpLink> links_;
  std::map<std::string, EventKey> events_;
  std::map<std::tuple<std::string, std::string, std::string>, std::string> by_key_;
};

// `s` lower-cased, with every character but [a-z0-9_] made '_' (YARP: a '.' in a carrier
// modifier is a space; a capital letter would break the event-name scheme).
std::string yarp_slug(const std::string& s);

}  // namespace arbc::codegen
