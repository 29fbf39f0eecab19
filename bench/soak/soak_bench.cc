// Soak (issue 8; docs/benchmarks.md "Soak (issue 8)"): pushes MESSAGES connection messages
// through a built app (bench/figures/soak.sh uses table_clean: 14 connections, generated Lua
// monitors, four arbitrated ports) in simulated time, and reports resident memory at the
// start and the end, so a leak per message shows as growth.
//
//   soak_bench APP_DIR [MESSAGES]     (default 100,000,000)
//
// Every module of the app is a stand-in: each output port publishes, every millisecond of
// simulated time, the next of 64 values drawn at random for its type (status lists are random
// sets of the app's event names, so feeds set and unset events and arbitration switches);
// input ports count what they receive. A "message" is one message entering one connection
// (ConnectionStats::arrived), the unit the runtime works in.
// Output: JSON lines {"name", "value", "unit"} like the other figures. Exits 1 if any message
// is unaccounted for (arrived != delivered + dropped + pending).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <string>

#include "runtime/app_loader.h"
#include "runtime/runtime.h"

namespace {

using namespace std::chrono_literals;

using namespace arbc;

// Resident set size of this process, in bytes (/proc/self/statm, second field, in pages).
double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  long pages_total = 0, pages_resident = 0;
  statm >> pages_total >> pages_resident;
  return static_cast<double>(pages_resident) * 4096.0;
}

// A random value of type t; strings come from `words`.
Value random_value(const Type& t, std::mt19937_64& rng, const std::vector<std::string>& words) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  switch (t.kind) {
    case Type::Kind::Bool:
      return Value(unit(rng) < 0.5);
    case Type::Kind::Int:
      return Value(static_cast<int64_t>(rng() % 10));
    case Type::Kind::Float:
      return Value(unit(rng));
    case Type::Kind::String:
      return Value(words[rng() % words.size()]);
    case Type::Kind::Vec3:
      return Value(Eigen::Vector3d(unit(rng), unit(rng) - 0.5, 0.0));
    case Type::Kind::List: {
      ValueList items;
      if (t.element->kind == Type::Kind::String) {
        for (const std::string& w : words) {
          if (unit(rng) < 0.5) items.push_back(Value(w));  // a status: a random set of flags
        }
      } else {
        for (size_t n = rng() % 4; n > 0; --n)
          items.push_back(random_value(*t.element, rng, words));
      }
      return Value(std::move(items));
    }
    case Type::Kind::Record: {
      ValueRecord fields;
      for (const Field& f : t.fields) fields.emplace(f.name, random_value(*f.type, rng, words));
      return Value(std::move(fields));
    }
  }
  return Value();
}

// Stands in for any module of the app: publishes on each output port every millisecond.
class StandIn : public Module {
 public:
  StandIn(const model::Module& m, const std::vector<std::string>& words) {
    std::mt19937_64 rng(std::hash<std::string>{}(m.name));
    for (const model::Port& p : m.ports) {
      if (p.direction == model::Direction::In) {
        in(p.name, p.type->to_string());
        continue;
      }
      out(p.name, p.type->to_string());
      Output o{p.name, {}};
      for (int i = 0; i < 64; ++i) o.values.push_back(random_value(*p.type, rng, words));
      outputs_.push_back(std::move(o));
    }
  }
  double tick_period() const override { return outputs_.empty() ? 0 : 0.001; }
  void tick() override {
    for (Output& o : outputs_) publish(o.port, o.values[next_++ % o.values.size()]);
  }
  void on_message(const std::string&, const Value&) override { ++received; }
  uint64_t received = 0;

 private:
  struct Output {
    std::string port;
    std::vector<Value> values;
  };
  std::vector<Output> outputs_;
  size_t next_ = 0;
};

uint64_t arrived(const Runtime& rt) {
  uint64_t n = 0;
  for (const ConnectionStats& s : rt.stats()) n += s.arrived;
  return n;
}

size_t lua_bytes(const Runtime& rt) {
  size_t n = 0;
  for (const auto& [name, bytes] : rt.monitor_memory()) n += bytes;
  return n;
}

void figure(const char* name, double value, const char* unit) {
  std::printf("{\"name\": \"%s\", \"value\": %.6g, \"unit\": \"%s\"}\n", name, value, unit);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: soak_bench APP_DIR [MESSAGES]\n");
    return 2;
  }
  const uint64_t target = argc > 2 ? std::stoull(argv[2]) : 100'000'000ull;
  std::string load_error;
  std::optional<model::App> app = load_app_dir(argv[1], &load_error);
  if (!app) {
    std::fprintf(stderr, "soak_bench: %s\n", load_error.c_str());
    return 2;
  }
  std::vector<std::string> words;
  for (const model::Event& e : app->events) words.push_back(e.name);
  if (words.empty()) words.push_back("x");
  Registry registry;
  for (const model::Module& m : app->modules) {
    registry.add_module(m.name, [&m, &words] { return std::make_unique<StandIn>(m, words); });
  }
  RunOptions options;
  options.duration = 1e12;
  std::string error;
  auto rt = Runtime::create(*app, argv[1], options, &error, registry);
  if (!rt) {
    std::fprintf(stderr, "soak_bench: %s\n", error.c_str());
    return 2;
  }
  rt->set_reporter(
      [](const std::string& line) { std::fprintf(stderr, "soak: %s\n", line.c_str()); });
  rt->start();
  const double rss_before = resident_bytes();

  // Warm-up: the first 1% (allocator pools, Lua states, queues reach their working size).
  Nanos t{0};
  while (arrived(*rt) < target / 100) rt->advance(t += 1s);
  const double rss_start = resident_bytes();
  const size_t lua_start = lua_bytes(*rt);
  const uint64_t counted_from = arrived(*rt);
  auto wall_start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  double rss_peak = rss_start;
  uint64_t next_sample = counted_from + target / 10;
  while (arrived(*rt) < target) {
    rt->advance(t += 1s);
    if (arrived(*rt) >= next_sample) {
      rss_peak = std::max(rss_peak, resident_bytes());
      next_sample += target / 10;
    }
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const double rss_end = resident_bytes();
  const uint64_t total = arrived(*rt);
  uint64_t delivered = 0, dropped = 0, pending = 0, errors = 0;
  for (const ConnectionStats& s : rt->stats()) {
    delivered += s.delivered;
    for (uint64_t d : s.dropped) dropped += d;
    pending += s.pending;
    errors += s.errors;
  }
  const size_t lua_end = lua_bytes(*rt);
  rt->shutdown();

  constexpr double kMiB = 1024.0 * 1024.0;
  figure("soak_messages", static_cast<double>(total), "messages");
  figure("soak_delivered", static_cast<double>(delivered), "messages");
  figure("soak_dropped", static_cast<double>(dropped), "messages");
  figure("soak_script_errors", static_cast<double>(errors), "errors");
  figure("soak_simulated_time", seconds_of(t), "s");
  figure("soak_wall_time", wall, "s");
  figure("soak_cpu_time", cpu, "s");
  // Per CPU second: what the runtime sustains; the wall rate depends on the other jobs.
  figure("soak_rate", static_cast<double>(total - counted_from) / cpu, "messages/s");
  figure("soak_rate_wall", static_cast<double>(total - counted_from) / wall, "messages/s");
  figure("soak_rss_before_messages", rss_before / kMiB, "MiB");
  figure("soak_rss_start", rss_start / kMiB, "MiB");
  figure("soak_rss_end", rss_end / kMiB, "MiB");
  figure("soak_rss_peak", rss_peak / kMiB, "MiB");
  figure("soak_rss_growth", (rss_end - rss_start) / kMiB, "MiB");
  figure("soak_lua_memory_start", static_cast<double>(lua_start) / 1024.0, "KiB");
  figure("soak_lua_memory_end", static_cast<double>(lua_end) / 1024.0, "KiB");
  // No message may disappear, even after 10^8 of them.
  if (total != delivered + dropped + pending) {
    std::fprintf(
        stderr, "soak_bench: %llu arrived but %llu delivered + %llu dropped + %llu pending\n",
        static_cast<unsigned long long>(total), static_cast<unsigned long long>(delivered),
        static_cast<unsigned long long>(dropped), static_cast<unsigned long long>(pending));
    return 1;
  }
  return 0;
}
