// What a mediator remembers of its own deliveries, kept in a file (`arbc run --state FILE`) so
// that a mediator started again (after a crash, a kill, an update) goes on from where the last
// one stopped instead of from the app's initial state (docs/runtime.md#a-mediator-that-restarts).
//
// Why: what a port delivered is a fact of the world that outlives the process. table_clean's arm
// holds the object a take delivered, and `e_take_open` (set by that take's delivery) is what
// lets the put through: a mediator that started again without it waits for a take that already
// happened, and the arm holds the object for ever. One that kept it but not when the last take
// was could deliver a second take within the second `never two take within 1s` forbids.
//
// What is kept, for the ports mediated here: the entries deliveries set (delivery events,
// `by priority` activity events) with their expiries; each rule's last delivery (throttles); the
// runtime checks' history of what the claims forbid (ClaimWatch::save). Times are instants of
// the run that wrote them; a restart maps them into its own run by the wall time that passed,
// times the run's time scale, so a lifetime keeps running while no mediator is up. What a claim
// owes within a window (a response) is not kept: the time without a mediator is part of no run.
//
// When: after every delivery, before the message leaves for its module, so that no delivery a
// module may have received is missing from the file (a kill between the two leaves one the
// module did not get: the memory errs towards having delivered). Nothing else changes it: the
// instants it keeps end lifetimes by themselves. Written to FILE.tmp, then renamed over FILE,
// so that a kill never leaves half a file.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/instant.h"

namespace arbc {

// The runtime checks' share of the memory (ClaimWatch save, load and resume), so that the
// runtime does not depend on what the checks keep.
struct MemoryHooks {
  std::function<nlohmann::json()> save;
  // Takes a saved history; false (with *error) when it does not fit this app's claims.
  std::function<bool(const nlohmann::json&, std::string* error)> load;
  // Applies what load took, its instants moved by `shift` into this run's time.
  std::function<void(Nanos shift)> resume;
};

// A memory file as read, before it is applied at the start of the run.
struct SavedMemory {
  struct Entry {
    std::string port, event, owner;  // owner: the connection whose entry it is
    Nanos expiry{0};                 // kNever: until unset
  };
  std::string file;
  Nanos time{0};        // the instant of the run that wrote it
  int64_t wall_ns = 0;  // the wall clock then (ns since the epoch)
  std::vector<Entry> entries;
  std::vector<std::pair<std::string, Nanos>> last_delivery;  // rule -> its last delivery
};

// The file's format, version 1; the fingerprint ties it to one build of one app.
nlohmann::json memory_json(const std::string& app, uint64_t fingerprint, const SavedMemory& m,
                           const nlohmann::json& checks);
// Reads `doc` into *m and *checks; false with *error (what is wrong, what to do) otherwise.
bool parse_memory(const nlohmann::json& doc, const std::string& app, uint64_t fingerprint,
                  SavedMemory* m, nlohmann::json* checks, std::string* error);
// Writes `doc` to path.tmp and renames it over `path`; false with *error.
bool write_memory_file(const std::string& path, const nlohmann::json& doc, std::string* error);
// How far the saved instants move into a run started at `start`: by the wall time since the
// file was written (never negative: a clock set back does not make time run backwards).
Nanos memory_shift(const SavedMemory& m, Nanos start, int64_t wall_now_ns, double time_scale);

}  // namespace arbc
