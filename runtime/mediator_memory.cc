// The mediator's memory (runtime/mediator_memory.h): its file format, and the Runtime's load at
// create, restore at start and save after each delivery.
#include "runtime/mediator_memory.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/duration_literal.h"
#include "core/join.h"
#include "runtime/runtime_internal.h"

namespace arbc {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kVersion = 1;

json instant(Nanos t) { return t == kNever ? json(nullptr) : json(t.count()); }

int64_t wall_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string hex(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

}  // namespace

json memory_json(const std::string& app, uint64_t fingerprint, const SavedMemory& m,
                 const json& checks) {
  json entries = json::array(), last = json::object();
  for (const SavedMemory::Entry& e : m.entries)
    entries.push_back(
        {{"port", e.port}, {"event", e.event}, {"owner", e.owner}, {"expiry", instant(e.expiry)}});
  for (const auto& [rule, t] : m.last_delivery) last[rule] = t.count();
  return {{"arbc_mediator_memory", kVersion},
          {"app", app},
          {"fingerprint", hex(fingerprint)},
          {"time", m.time.count()},
          {"wall_ns", m.wall_ns},
          {"entries", entries},
          {"last_delivery", last},
          {"checks", checks}};
}

bool parse_memory(const json& doc, const std::string& app, uint64_t fingerprint, SavedMemory* m,
                  json* checks, std::string* error) {
  const std::string what = m->file + ": ";
  const std::string fresh = "; remove it to start this mediator with no memory";
  try {
    if (!doc.is_object() || doc.value("arbc_mediator_memory", 0) != kVersion) {
      *error = what + "not a memory file of `arbc run --state` (version " +
               std::to_string(kVersion) + ")" + fresh + ", or give --state another file";
      return false;
    }
    if (doc.at("app").get<std::string>() != app || doc.at("fingerprint") != hex(fingerprint)) {
      *error = what + "written by a run of another build of app '" +
               doc.at("app").get<std::string>() +
               "' (its app.json differs from this one's): what it remembers may not fit" + fresh;
      return false;
    }
    m->time = Nanos(doc.at("time").get<int64_t>());
    m->wall_ns = doc.at("wall_ns").get<int64_t>();
    for (const json& e : doc.at("entries")) {
      const json& expiry = e.at("expiry");
      m->entries.push_back({e.at("port").get<std::string>(), e.at("event").get<std::string>(),
                            e.at("owner").get<std::string>(),
                            expiry.is_null() ? kNever : Nanos(expiry.get<int64_t>())});
    }
    for (const auto& [rule, t] : doc.at("last_delivery").items())
      m->last_delivery.emplace_back(rule, Nanos(t.get<int64_t>()));
    *checks = doc.at("checks");
  } catch (const json::exception& e) {
    *error = what + "not a memory file this version of arbc wrote (" + e.what() + ")" + fresh;
    return false;
  }
  return true;
}

bool write_memory_file(const std::string& path, const json& doc, std::string* error) {
  std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << doc.dump() << '\n';
    if (!out.flush()) {
      *error = tmp + ": cannot write the mediator's memory";
      return false;
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    *error = path + ": cannot replace it with " + tmp + ": " + ec.message();
    return false;
  }
  return true;
}

Nanos memory_shift(const SavedMemory& m, Nanos start, int64_t wall_now_ns, double time_scale) {
  double passed = std::max<double>(0, static_cast<double>(wall_now_ns - m.wall_ns)) * time_scale;
  // Past the longest run there is, every saved lifetime has ended anyway.
  passed = std::min(passed, static_cast<double>(kLongestDuration.count()));
  return start - m.time - Nanos(static_cast<int64_t>(std::llround(passed)));
}

// --- the Runtime's side -------------------------------------------------------------------

uint64_t Runtime::memory_fingerprint() const {
  std::ifstream in(options_.app_file, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return stable_hash(app_.name + "\n" + bytes.str());
}

Runtime::Connection* Runtime::memory_owner(const std::string& port, const std::string& name) {
  for (auto& c : connections_)
    if (c->name == name && c->destination->qualified == port) return c.get();
  return nullptr;
}

bool Runtime::load_memory(std::string* error) {
  const std::string& path = options_.state_path;
  if (path.empty()) return true;
  if (!options_.realtime) {
    *error = "--state " + path +
             ": a mediator's memory is for runs on the wall clock "
             "(--transport dds, yarp or --realtime); a simulated run starts afresh each time";
    return false;
  }
  memory_fingerprint_ = memory_fingerprint();
  if (!fs::exists(path)) return true;  // none yet: the first start
  std::ifstream in(path);
  json doc = json::parse(in, nullptr, /*allow_exceptions=*/false);
  auto m = std::make_unique<SavedMemory>();
  m->file = path;
  json checks;
  if (!parse_memory(doc, app_.name, memory_fingerprint_, m.get(), &checks, error)) return false;
  for (const SavedMemory::Entry& e : m->entries) {
    Connection* c = memory_owner(e.port, e.owner);
    if (!c || !c->destination->mediated) {
      *error = path + ": it remembers " + e.event + " at " + e.port + " set by '" + e.owner +
               "', which this mediator does not run; start it with the --mediate it had, or "
               "remove the file to start with no memory";
      return false;
    }
  }
  if (options_.checks_memory.load && !options_.checks_memory.load(checks, error)) {
    *error = path + ": " + *error;
    return false;
  }
  memory_ = std::move(m);
  return true;
}

void Runtime::restore_memory() {
  if (!memory_) return;
  Nanos t = start_time_;
  Nanos shift = memory_shift(*memory_, t, wall_now_ns(), options_.time_scale);
  std::vector<std::string> kept, lapsed;
  for (const SavedMemory::Entry& e : memory_->entries) {
    Connection* c = memory_owner(e.port, e.owner);
    Nanos expiry = e.expiry == kNever ? kNever : e.expiry + shift;
    if (expiry <= t) {
      lapsed.push_back(e.event + " at " + e.port);
      continue;
    }
    EventContainer& box = c->destination->container;
    box.set(box.index().intern(e.event), c->index, expiry);
    trace_.event(t, e.port, "set", e.event, c->name, expiry);
    kept.push_back(e.event + " at " + e.port +
                   (expiry == kNever ? "" : " for " + duration_literal(expiry - t)));
  }
  for (const auto& [rule, last] : memory_->last_delivery)
    for (auto& c : connections_)
      if (c->name == rule && c->destination->mediated) c->last_delivery = last + shift;
  if (options_.checks_memory.resume) options_.checks_memory.resume(shift);
  std::string line = "restored the memory in " + memory_->file + ", written " +
                     duration_literal(t - memory_->time - shift) +
                     " ago: " + (kept.empty() ? "no event set" : join(kept)) +
                     (lapsed.empty() ? "" : "; lapsed since: " + join(lapsed));
  trace_.log(t, "runtime", line);
  report(line);
  memory_.reset();
}

void Runtime::save_memory() {
  if (options_.state_path.empty()) return;
  SavedMemory m;
  m.time = now();
  m.wall_ns = wall_now_ns();
  for (auto& in : in_ports_) {
    if (!in->mediated) continue;
    in->container.for_each_entry([&](int event, int owner, Nanos expiry) {
      const Connection& c = *connections_[static_cast<size_t>(owner)];
      std::string name(in->container.index().name(event));
      bool by_delivery = c.delivered_from || c.model->set_on_delivery(name);
      if (by_delivery && expiry > m.time)
        m.entries.push_back({in->qualified, name, c.name, expiry});
    });
  }
  for (auto& c : connections_)
    if (!c->is_feed && c->destination->mediated && c->last_delivery != -kNever)
      m.last_delivery.emplace_back(c->name, c->last_delivery);
  json checks = options_.checks_memory.save ? options_.checks_memory.save() : json::object();
  std::string error;
  if (!write_memory_file(options_.state_path,
                         memory_json(app_.name, memory_fingerprint_, m, checks), &error) &&
      memory_errors_++ == 0) {
    report(error +
           " (the run goes on; a mediator started again would not know what this one "
           "delivered since)");
  }
}

}  // namespace arbc
