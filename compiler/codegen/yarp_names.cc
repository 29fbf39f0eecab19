#include "compiler/codegen/yarp_names.h"

#include <algorithm>
#include <set>
#include <tuple>

namespace arbc::codegen {

std::string yarp_slug(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    bool ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    out += ok ? c : '_';
  }
  return out;
}

namespace {

// A file name for YARP's `file.` modifier: letters, digits and '_' only.
std::string file_safe(const std::string& s) {
  std::string out;
  for (char c : s) {
    bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    out += ok ? c : '_';
  }
  return out;
}

}  // namespace

YarpNames::YarpNames(const model::App& app, std::map<std::string, std::string> ports)
    : ports_(std::move(ports)), app_(app) {
  make_links(app);
  make_events(app);
}

std::string YarpNames::port(const std::string& qualified) const {
  auto it = ports_.find(qualified);
  if (it != ports_.end()) return it->second;
  const model::Port* p = app_.find_port(qualified);
  size_t dot = qualified.find('.');
  std::string module = qualified.substr(0, dot), name = qualified.substr(dot + 1);
  bool out = p && p->direction == model::Direction::Out;
  return "/" + module + "/" + name + (out ? ":o" : ":i");
}

void YarpNames::make_links(const model::App& app) {
  std::map<std::pair<std::string, std::string>, size_t> index;
  for (size_t i = 0; i < app.connections.size(); ++i) {
    const model::Connection& c = app.connections[i];
    auto [it, fresh] = index.emplace(std::make_pair(c.source, c.destination), links_.size());
    if (fresh) links_.push_back({c.source, c.destination, {}, {}, {}, {}});
    YarpLink& l = links_[it->second];
    l.parts.push_back(i);
    if (c.kind != model::ConnectionKind::Feed && !l.delivering) l.delivering = i;
  }
  std::set<std::string> files;
  for (YarpLink& l : links_) {
    const model::Connection& named = app.connections[l.delivering ? *l.delivering : l.parts[0]];
    l.id = named.name;
    bool arbitrated = app.find_arbitrated(l.destination) != nullptr;
    bool plain = l.parts.size() == 1 && !arbitrated && named.monitor.empty();
    if (plain) continue;
    std::string base = file_safe(l.destination) + "__" + file_safe(named.name), name = base;
    for (int n = 2; !files.insert(name).second; ++n) name = base + "_" + std::to_string(n);
    l.monitor = name;
  }
}

void YarpNames::make_events(const model::App& app) {
  // (port, event, owner) in model order: ports by connection order, owners likewise.
  std::vector<std::tuple<std::string, std::string, std::string>> keys;
  for (const model::Connection& c : app.connections) {
    if (!app.find_arbitrated(c.destination)) continue;
    for (const std::string& e : c.sets) keys.emplace_back(c.destination, e, c.name);
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::map<std::pair<std::string, std::string>, int> owners;
  for (const auto& [port, event, owner] : keys) ++owners[{port, event}];
  size_t width = std::to_string(keys.size()).size();
  for (size_t i = 0; i < keys.size(); ++i) {
    const auto& [port, event, owner] = keys[i];
    std::string n = std::to_string(i + 1);
    n.insert(0, width - n.size(), '0');
    std::string name = "E" + n + "_" + yarp_slug(port) + "__" + yarp_slug(event);
    if (owners[{port, event}] > 1) name += "__" + yarp_slug(owner);
    by_key_[keys[i]] = name;
    events_[name] = {port, event, owner};
  }
}

std::string YarpNames::event(const std::string& port, const std::string& event,
                             const std::string& owner) const {
  auto it = by_key_.find({port, event, owner});
  return it == by_key_.end() ? std::string() : it->second;
}

std::vector<std::string> YarpNames::owners_of(const std::string& port,
                                              const std::string& event) const {
  std::vector<std::string> out;
  for (const model::Connection& c : app_.connections) {
    if (c.destination != port) continue;
    std::string n = YarpNames::event(port, event, c.name);
    if (!n.empty() && std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
  }
  return out;
}

}  // namespace arbc::codegen
