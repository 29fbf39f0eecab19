#include "harness/claim_expect.h"

#include <set>
#include <unordered_map>

#include "compiler/codegen/claims_writer.h"
#include "runtime/data_claims.h"
#include "runtime/decision_watch.h"
#include "runtime/delivery_watch.h"
#include "runtime/trace_container.h"

namespace arbc::harness {

namespace {

// An assert over `emitted` on `app`, which states only it: the claims script `arbc build` would
// write for it (compiler/codegen/claims_writer.h), judged on each delivery of its rule by the
// runtime's own check (runtime/delivery_watch.h), on the values the stand-ins received.
std::optional<ClaimBreach> data_assert_breach(model::App app, const model::Expectation& e,
                                              const TestRun& run) {
  app.resources.clear();
  lower::LoweredApp low;
  low.app = std::move(app);
  std::optional<std::string> script = codegen::write_claims(low);
  std::string err = "no claim";
  std::unique_ptr<DataClaims> claims =
      script ? DataClaims::load(low.app, *script, codegen::kClaimsScript, &err) : nullptr;
  if (!claims) return ClaimBreach{Nanos{0}, "the assert cannot be judged: " + err};
  std::unordered_map<std::string, TraceContainer> boxes{{e.port, TraceContainer()}};
  DeliveryWatch watch(low.app, claims.get(), boxes);
  for (const Received& got : run.received) {
    if (got.port != e.port || got.connection != e.assertion->rule) continue;
    TraceRecord r;
    r.t = got.t, r.kind = TraceKind::Deliver, r.port = got.port, r.connection = got.connection;
    r.value = &got.value;
    std::vector<DeliveryWatch::Breach> broke;
    watch.delivered(r, e.port, &broke);
    if (!broke.empty()) return ClaimBreach{got.t, broke[0].what};
  }
  return std::nullopt;
}

// The value each delivery of the run carried, in order: the stand-ins received them (a trace
// keeps no values). A delivery without its value is judged as the runtime judges one.
class DeliveredValues {
 public:
  explicit DeliveredValues(const std::vector<Received>& received) : received_(received) {}
  const Value* of(const TraceRecord& r) {
    for (size_t i = next_; i < received_.size(); ++i) {
      const Received& got = received_[i];
      if (got.t > r.t) break;
      if (got.t == r.t && got.port == r.port && got.connection == r.connection) {
        next_ = i + 1;
        return &got.value;
      }
    }
    return nullptr;
  }

 private:
  const std::vector<Received>& received_;
  size_t next_ = 0;
};

// `expect resource R;` on `app`, which keeps only R: judged by the runtime's own check
// (runtime/delivery_watch.h) over the containers of R's ports, rebuilt from the event records,
// and each delivery into them with the value its stand-in received.
std::optional<ClaimBreach> resource_breach(model::App app, const model::Expectation& e,
                                           const TestRun& run) {
  std::erase_if(app.resources, [&](const model::Resource& r) { return r.name != e.resource; });
  if (app.resources.empty()) return std::nullopt;  // sema said so
  for (model::ArbitratedPort& p : app.arbitrated_ports) p.asserts.clear();
  lower::LoweredApp low;
  low.app = std::move(app);
  std::unique_ptr<DataClaims> claims;
  if (low.app.resources[0].uses) {
    std::optional<std::string> script = codegen::write_claims(low);
    std::string err = "no claim";
    if (script) claims = DataClaims::load(low.app, *script, codegen::kClaimsScript, &err);
    if (!claims) return ClaimBreach{Nanos{0}, "the resource cannot be judged: " + err};
  }
  std::unordered_map<std::string, TraceContainer> boxes;
  for (const std::string& port : low.app.resources[0].ports) boxes[port];
  DeliveryWatch watch(low.app, claims.get(), boxes);
  DeliveredValues values(run.received);
  for (const TraceRecord& r : run.records) {
    TraceLine line = trace_line_of(r);
    watch.before(line);
    auto box = boxes.find(r.port);
    if (box == boxes.end()) continue;
    if (r.kind == TraceKind::Event) {
      box->second.apply(r);
      watch.after(line, r.port);
    } else if (r.kind == TraceKind::Deliver) {
      line.value = values.of(r);
      std::vector<DeliveryWatch::Breach> broke;
      watch.delivered(line, r.port, &broke);
      if (!broke.empty()) return ClaimBreach{r.t, broke[0].what};
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<ClaimBreach> claim_breach(const model::Expectation& e, const TestRun& run) {
  if (e.kind == model::Expectation::Kind::Resource && run.app)
    return resource_breach(*run.app, e, run);
  if (!run.app || !run.app->find_arbitrated(e.port)) return std::nullopt;  // sema said so
  // The app with only the claim the test states: the watch judges that, not the asserts the
  // app declares (a kept counterexample still states its assert once the app drops it).
  model::App app = *run.app;
  std::string claim;
  for (model::ArbitratedPort& p : app.arbitrated_ports) {
    p.asserts.clear();
    if (p.port != e.port) continue;
    if (e.kind == model::Expectation::Kind::Assert && e.assertion) {
      p.asserts.push_back(*e.assertion);
      claim = model::assertion_text(p.port, *e.assertion);
    } else {
      claim = DecisionWatch::exclusivity_claim(p);
    }
  }
  if (e.kind == model::Expectation::Kind::Assert && e.assertion && e.assertion->emitted)
    return data_assert_breach(std::move(app), e, run);
  std::optional<ClaimBreach> out;
  DecisionWatch watch(
      app, [&e](const std::string& port) { return port == e.port; }, true,
      [&](const std::string& broken, Nanos t, const std::string& what) {
        if (broken == claim && !out) out = ClaimBreach{t, what};
      });
  std::set<std::string> rules;  // the port's rules: their decisions are judged
  for (const model::Connection* c : app.connections_into(e.port))
    if (c->kind == model::ConnectionKind::Rule) rules.insert(c->name);
  // As runtime/claim_watch.cc does: the port's container from its event records, and each
  // decision of a rule (a delivery, or a drop that is not a feed's) in the state at its instant.
  TraceContainer box;
  for (const TraceRecord& r : run.records) {
    if (r.kind == TraceKind::Event && r.port == e.port) {
      box.apply(r);
    } else if ((r.kind == TraceKind::Deliver && r.port == e.port) ||
               (r.kind == TraceKind::Drop && r.reason != DropReason::Feed)) {
      if (rules.count(r.connection)) watch.decision(r, box.present(r.t));
    }
    if (out) break;
  }
  return out;
}

}  // namespace arbc::harness
