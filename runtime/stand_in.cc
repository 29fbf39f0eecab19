#include "runtime/stand_in.h"

#include <algorithm>

#include "core/duration_literal.h"
#include "runtime/stand_in_sample.h"

namespace arbc {

namespace {

// A module of the app that no plugin provides (stand_in.h).
class StandIn : public Module {
 public:
  StandIn(const model::Module& m, const model::App& app, std::shared_ptr<StandInLog> log)
      : name_(m.name), log_(std::move(log)) {
    for (const model::Port& p : m.ports) {
      if (p.direction == model::Direction::In) {
        in(p.name, p.type->to_string());
        continue;
      }
      out(p.name, p.type->to_string());
      outs_.push_back({p.name, p.type, sample_plan(app, m.name + "." + p.name)});
    }
  }

  void start() override {
    log_->publishers[name_] = [this](const TimedValue& v) { send(v.port, v.value); };
    if (!log_->inputs_scheduled) {
      log_->inputs_scheduled = true;
      schedule_instants();
    }
    if (!log_->stub.enabled) return;
    for (const OutPort& o : outs_) {
      std::string qualified = name_ + "." + o.name;
      if (log_->inputs_on(qualified)) continue;  // an inputs file speaks for this port
      auto rate = log_->stub.period_of_port.find(qualified);
      double period =
          rate == log_->stub.period_of_port.end() ? log_->stub.default_period : rate->second;
      if (period > 0) sample(o, now_nanos(), period, 0);
    }
  }

  void stop() override { log_->publishers.erase(name_); }

  void on_delivery(const Delivery& d) override {
    Received r{nanos_from_seconds(d.time), name_ + "." + d.port, d.connection, d.value};
    ReceivedTally& tally = log_->tally[r.port];
    if (tally.count++ == 0) tally.first = r.t;
    if (log_->keep_received) log_->received.push_back(r);
    tally.last = std::move(r);
  }

 private:
  struct OutPort {
    std::string name;
    TypePtr type;
    SamplePlan plan;  // what --stub draws (runtime/stand_in_sample.h)
  };

  // The first input of each instant at its time; play() goes on from there.
  void schedule_instants() {
    const std::vector<TimedValue>& in = log_->inputs();
    for (size_t i = 0; i < in.size(); ++i) {
      if (i > 0 && in[i - 1].t == in[i].t) continue;
      schedule(seconds_of(in[i].t - now_nanos()), [this, i] { play(i); });
    }
  }

  // Publishes input i on its stand-in's port (none runs here in a distributed run that hosts
  // its module elsewhere), then the next input of the same instant behind what this one
  // caused: a publication posts one task per message on each connection from the port
  // (runtime/message_path.cc), and a timer of delay 0 runs after them. Inputs of one instant
  // published at once would be processed connection by connection instead, not as listed.
  void play(size_t i) {
    const std::vector<TimedValue>& in = log_->inputs();
    auto publisher = log_->publishers.find(in[i].port.substr(0, in[i].port.find('.')));
    if (publisher != log_->publishers.end()) publisher->second(in[i]);
    if (i + 1 < in.size() && in[i + 1].t == in[i].t) schedule(0, [this, i] { play(i + 1); });
  }

  void send(const std::string& qualified, const Value& v) {
    ++log_->published[qualified];
    publish(qualified.substr(name_.size() + 1), v);
  }

  // The module API's seconds as the runtime's instant (exact under 2^21 s).
  Nanos now_nanos() const { return nanos_from_seconds(now()); }

  // Publishes sample k on `o` now, at origin + k * period (to the nanosecond), and schedules
  // the next (no drift).
  void sample(const OutPort& o, Nanos origin, double period, uint64_t k) {
    send(name_ + "." + o.name, sample_value(*o.type, rng(), o.plan));
    Nanos next = later(origin, nanos_from_seconds(static_cast<double>(k + 1) * period));
    schedule(seconds_of(next - now_nanos()),
             [this, &o, origin, period, k] { sample(o, origin, period, k + 1); });
  }

  std::string name_;
  std::shared_ptr<StandInLog> log_;
  std::vector<OutPort> outs_;
};

}  // namespace

void StandInLog::add_input(TimedValue v) {
  auto after = std::upper_bound(inputs_.begin(), inputs_.end(), v.t,
                                [](Nanos t, const TimedValue& x) { return t < x.t; });
  inputs_.insert(after, std::move(v));
}

uint64_t StandInLog::inputs_on(const std::string& port) const {
  uint64_t n = 0;
  for (const TimedValue& v : inputs_) n += v.port == port;
  return n;
}

Registry registry_with_stand_ins(const model::App& app, const Registry& base,
                                 std::shared_ptr<StandInLog> log,
                                 std::vector<std::string>* stand_ins) {
  Registry out = base;
  auto shared_app = std::make_shared<model::App>(app);  // the factories outlive the caller's app
  for (const model::Module& m : app.modules) {
    if (base.find_module(m.name)) continue;
    stand_ins->push_back(m.name);
    out.add_module(m.name,
                   [m, shared_app, log] { return std::make_unique<StandIn>(m, *shared_app, log); });
  }
  return out;
}

std::string stand_in_summary(const model::App& app, const std::vector<std::string>& stand_ins,
                             const StandInLog& log) {
  std::string out;
  for (const std::string& name : stand_ins) {
    const model::Module* m = app.find_module(name);
    if (!m) continue;
    for (const model::Port& p : m->ports) {
      std::string q = name + "." + p.name;
      if (p.direction == model::Direction::Out) {
        auto it = log.published.find(q);
        uint64_t n = it == log.published.end() ? 0 : it->second;
        out += "  " + q + " (stand-in source): published " + std::to_string(n);
        // Inputs timed after the run's end (or an interrupt) never go out: say so, rather
        // than let a short --duration drop them unseen.
        uint64_t scripted = log.inputs_on(q);
        if (scripted > n) {
          out += " of the " + std::to_string(scripted) + " in the inputs (" +
                 std::to_string(scripted - n) + " not reached: the run ended first)";
        }
        out += "\n";
        continue;
      }
      auto tally = log.tally.find(q);
      uint64_t got = tally == log.tally.end() ? 0 : tally->second.count;
      out += "  " + q + " (stand-in sink): received " + std::to_string(got);
      if (got) {
        // As a test's expectation writes them (`expect P receives at 2.9s`).
        const Received& last = tally->second.last;
        out += ", first at " + duration_literal(tally->second.first) + ", last at " +
               duration_literal(last.t) + " (" + last.connection + "): " + last.value.to_json();
      }
      out += "\n";
    }
  }
  return out.empty() ? out : "stand-ins:\n" + out;
}

}  // namespace arbc
