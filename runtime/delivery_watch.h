// The runtime checks of what the proof claims about delivered values (issue 39; ClaimWatch
// feeds it every trace record):
//   - each assert over data (`assert P: RULE -> PREDICATE over emitted`): every delivery of RULE
//     into P satisfies it;
//   - each resource: no two ports of it receive a command that uses it (its `when` holds, or it
//     has none) in one event state, the state the first delivery left (its own delivery events
//     and activity events applied), with no change of the ports' events in between, which is
//     what `arbc verify` proves for every pair of its rules (docs/checks.md#resource).
// The predicates run as the claims script `arbc build` wrote (runtime/data_claims.h); without
// one (an app built by an older arbc, or a model made in code) only resources without `when`
// are watched.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/app_model.h"
#include "runtime/data_claims.h"
#include "runtime/trace_container.h"
#include "runtime/trace_format.h"

namespace arbc {

class DeliveryWatch {
 public:
  struct Breach {
    std::string claim, what;
  };
  // `boxes` are the arbitrated ports' containers as the trace shows them (ClaimWatch's),
  // `claims` the loaded claims script (null: none).
  DeliveryWatch(const model::App& app, DataClaims* claims,
                const std::unordered_map<std::string, TraceContainer>& boxes);

  bool empty() const { return asserts_.empty() && resources_.empty(); }
  std::vector<std::string> watched() const;
  // Whether a record about `port`'s events may change what the resources see: call before()
  // and after() around applying it.
  bool watches_port(std::string_view port) const { return resource_ports_.count(port) > 0; }
  void before(const TraceLine& r);
  void after(const TraceLine& r, const std::string& port);
  // A delivery of `rule` into its arbitrated port `port`: what it broke, into *out.
  void delivered(const TraceLine& r, const std::string& port, std::vector<Breach>* out);
  void delivered(const TraceRecord& r, const std::string& port, std::vector<Breach>* out) {
    delivered(trace_line_of(r), port, out);
  }

 private:
  struct Assert {
    size_t claim;  // index into DataClaims::claims()
    std::string port, rule, text;
  };
  struct Use {  // the last delivery that used a resource
    std::string port, rule;
    std::optional<Value> value;
    Nanos t{0};
    bool settled = false;                      // its effects applied: the state it left is known
    uint64_t changes = 0;                      // the resource's changes count then
    std::vector<std::set<std::string>> state;  // then, per port of the resource
  };
  struct Watched {
    const model::Resource* r;
    std::optional<size_t> uses;  // the claim of its `when`
    uint64_t changes = 0;        // presence changes in its ports' containers
    std::optional<Use> last;
  };

  void settle(Watched& w, Nanos t);
  bool same_state(const Watched& w, Nanos t) const;
  bool uses(const Watched& w, const Value* v);

  DataClaims* claims_;
  const std::unordered_map<std::string, TraceContainer>& boxes_;
  std::vector<Assert> asserts_;
  std::vector<Watched> resources_;
  std::set<std::string, std::less<>> resource_ports_;
  bool present(const TraceLine& r, const std::string& port) const;  // r's event, in port
  bool was_present_ = false;  // before(): the record's event, before it
};

}  // namespace arbc
