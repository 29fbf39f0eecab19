// Differential test: random ports verified by arbc (Z3) and by brute-force enumeration of every
// event state. Verdicts must be identical, and every counterexample valid and minimal.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

#include "core/app_json.h"
#include "verify/verify.h"

namespace arbc::verify {
namespace {

constexpr int kPorts = 1000;
constexpr int kMaxEvents = 12;
constexpr int kMaxRules = 8;

class Generator {
 public:
  explicit Generator(uint32_t seed) : rng_(seed) {}

  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  bool chance(int percent) { return below(100) < percent; }

  Constraint formula(int n_events, int depth) {
    if (depth == 0 || chance(35)) {
      if (chance(4)) return Constraint::constant(chance(50));
      return Constraint::event_ref(event(n_events));
    }
    int kind = below(3);
    if (kind == 0) return Constraint::negate(formula(n_events, depth - 1));
    std::vector<Constraint> args;
    for (int i = 0, k = 2 + below(2); i < k; ++i) args.push_back(formula(n_events, depth - 1));
    return kind == 1 ? Constraint::conjunction(args) : Constraint::disjunction(args);
  }

  // A conjunction of 1..4 literals: the usual shape of a rule guard.
  Constraint cube(int n_events) {
    std::vector<Constraint> lits;
    for (int i = 0, k = 1 + below(4); i < k; ++i) {
      Constraint e = Constraint::event_ref(event(n_events));
      lits.push_back(chance(50) ? e : Constraint::negate(e));
    }
    return Constraint::conjunction(lits);
  }

  std::vector<std::string> subset(int n_events, int percent) {
    std::vector<std::string> out;
    for (int i = 0; i < n_events; ++i) {
      if (chance(percent)) out.push_back(name(i));
    }
    return out;
  }

  static std::string name(int i) { return "e" + std::to_string(i); }
  std::string event(int n_events) { return name(below(n_events)); }

 private:
  std::mt19937 rng_;
};

model::App random_app(Generator& g) {
  model::App app;
  app.name = "random";
  int n = 1 + g.below(kMaxEvents);
  int m = 1 + g.below(kMaxRules);
  model::ArbitratedPort port;
  port.port = "M.p";
  port.complete = g.chance(30);
  for (int r = 0; r < m; ++r) {
    model::Connection c;
    c.name = "r" + std::to_string(r);
    c.source = "S.o" + std::to_string(r);
    c.destination = port.port;
    c.constraint = g.chance(50) ? g.cube(n) : g.formula(n, 3);
    if (g.chance(30)) c.must_set = g.subset(n, 15);
    if (g.chance(20)) c.must_unset = g.subset(n, 15);
    c.sets = c.must_set;
    c.sets.insert(c.sets.end(), c.must_unset.begin(), c.must_unset.end());
    c.unsets = c.must_unset;
    c.opaque = g.chance(5);
    port.rules.push_back(c.name);
    app.connections.push_back(std::move(c));
  }
  model::Connection feed;
  feed.name = "feed";
  feed.source = "S.status";
  feed.destination = port.port;
  feed.kind = model::ConnectionKind::Feed;
  feed.constraint = Constraint::constant(false);
  feed.sets = g.subset(n, 60);
  app.connections.push_back(std::move(feed));
  for (int i = 0, k = g.below(3); i < k; ++i) app.invariants.push_back({g.formula(n, 2), {}});
  for (int i = 0, k = g.below(3); i < k; ++i) {
    std::vector<std::string> group = g.subset(n, 25);
    if (group.size() >= 2) app.exclusive_groups.push_back({group, {}});
  }
  for (int i = 0, k = g.below(3); i < k; ++i) {
    port.asserts.push_back({port.rules[static_cast<size_t>(g.below(m))], g.formula(n, 2), {}, {}});
  }
  app.arbitrated_ports.push_back(std::move(port));
  return app;
}

// The reference semantics, written independently of verify/: docs/design.md#the-proof by
// enumeration.
struct BruteForce {
  int n = 0;
  const model::App* app = nullptr;

  std::set<std::string> state(uint32_t bits) const {
    std::set<std::string> s;
    for (int i = 0; i < n; ++i) {
      if (bits >> i & 1) s.insert(Generator::name(i));
    }
    return s;
  }
  std::vector<const model::Invariant*> invariants;  // those touching the port, transitively
  std::vector<const model::ExclusiveGroup*> groups;

  // A `script` rule (opaque) may set any event, whatever its `sets` say.
  bool other_sets(const model::Connection& c, const std::string& e) const {
    for (const model::Connection& o : app->connections) {
      if (&o != &c && (o.opaque || std::count(o.sets.begin(), o.sets.end(), e))) return true;
    }
    return false;
  }

  // docs/design.md#the-proof: the port's events are those its effective guards and asserts read;
  // the domain is the invariants and groups that mention them, closed transitively.
  void select_domain() {
    std::set<std::string> scope;
    for (const model::Connection& c : app->connections) {
      if (c.kind != model::ConnectionKind::Rule) continue;
      c.constraint.collect_events(scope);
      if (c.opaque) continue;
      scope.insert(c.must_set.begin(), c.must_set.end());
      for (const std::string& e : c.must_unset) {
        if (!other_sets(c, e)) scope.insert(e);
      }
    }
    for (const model::Assertion& a : app->arbitrated_ports[0].asserts)
      a.property.collect_events(scope);
    std::vector<bool> used_inv(app->invariants.size()), used_group(app->exclusive_groups.size());
    for (bool grew = true; grew;) {
      grew = false;
      for (size_t i = 0; i < app->invariants.size(); ++i) {
        std::set<std::string> ev;
        app->invariants[i].formula.collect_events(ev);
        if (used_inv[i] ||
            std::none_of(ev.begin(), ev.end(), [&](auto& e) { return scope.count(e); }))
          continue;
        used_inv[i] = grew = true;
        scope.insert(ev.begin(), ev.end());
      }
      for (size_t i = 0; i < app->exclusive_groups.size(); ++i) {
        const auto& ev = app->exclusive_groups[i].events;
        if (used_group[i] ||
            std::none_of(ev.begin(), ev.end(), [&](auto& e) { return scope.count(e); }))
          continue;
        used_group[i] = grew = true;
        scope.insert(ev.begin(), ev.end());
      }
    }
    for (size_t i = 0; i < used_inv.size(); ++i) {
      if (used_inv[i]) invariants.push_back(&app->invariants[i]);
    }
    for (size_t i = 0; i < used_group.size(); ++i) {
      if (used_group[i]) groups.push_back(&app->exclusive_groups[i]);
    }
  }

  bool domain(const std::set<std::string>& s) const {
    for (const model::Invariant* inv : invariants) {
      if (!evaluate(inv->formula, s)) return false;
    }
    for (const model::ExclusiveGroup* gp : groups) {
      const model::ExclusiveGroup& g = *gp;
      int present = 0;
      for (const std::string& e : g.events) present += s.count(e) > 0;
      if (present > 1) return false;
    }
    return true;
  }
  bool holds(size_t rule, const std::set<std::string>& s) const {
    const model::Connection& c = app->connections[rule];
    if (!evaluate(c.constraint, s)) return false;
    if (c.opaque) return true;
    for (const std::string& e : c.must_set) {
      if (!s.count(e)) return false;
    }
    for (const std::string& e : c.must_unset) {
      if (!other_sets(c, e) && s.count(e)) return false;
    }
    return true;
  }
  size_t rule_index(const std::string& name) const {
    for (size_t i = 0; i < app->connections.size(); ++i) {
      if (app->connections[i].name == name) return i;
    }
    return SIZE_MAX;
  }
};

std::set<std::string> as_set(const std::vector<std::string>& v) { return {v.begin(), v.end()}; }

TEST(Differential, RandomPortsAgreeWithBruteForce) {
  Generator g(20261122);
  int compared = 0, refuted = 0, proved = 0, skipped = 0;
  while (compared < kPorts) {
    model::App app = random_app(g);
    BruteForce bf;
    bf.app = &app;
    bf.select_domain();
    bf.n = 0;
    for (const model::Connection& c : app.connections) {
      std::set<std::string> ev;
      c.constraint.collect_events(ev);
      ev.insert(c.sets.begin(), c.sets.end());
      for (const std::string& e : ev) bf.n = std::max(bf.n, std::stoi(e.substr(1)) + 1);
    }
    for (const model::Invariant& i : app.invariants) {
      std::set<std::string> ev;
      i.formula.collect_events(ev);
      for (const std::string& e : ev) bf.n = std::max(bf.n, std::stoi(e.substr(1)) + 1);
    }
    for (const model::ExclusiveGroup& gr : app.exclusive_groups) {
      for (const std::string& e : gr.events) bf.n = std::max(bf.n, std::stoi(e.substr(1)) + 1);
    }
    for (const model::Assertion& a : app.arbitrated_ports[0].asserts) {
      std::set<std::string> ev;
      a.property.collect_events(ev);
      for (const std::string& e : ev) bf.n = std::max(bf.n, std::stoi(e.substr(1)) + 1);
    }
    const model::ArbitratedPort& port = app.arbitrated_ports[0];
    size_t m = port.rules.size();

    // Enumerate every state.
    const size_t none = SIZE_MAX;
    bool any_state = false;
    std::vector<bool> can_hold(m, false);
    std::map<std::pair<size_t, size_t>, size_t> pair_min;  // overlapping pair -> fewest events
    size_t complete_min = none;
    std::vector<size_t> assert_min(port.asserts.size(), none);
    for (uint32_t bits = 0; bits < (1u << bf.n); ++bits) {
      std::set<std::string> s = bf.state(bits);
      if (!bf.domain(s)) continue;
      any_state = true;
      std::vector<bool> h(m);
      for (size_t i = 0; i < m; ++i) h[i] = bf.holds(i, s);
      bool some = false;
      for (size_t i = 0; i < m; ++i) {
        some |= h[i];
        if (!h[i]) continue;
        can_hold[i] = true;
        for (size_t j = i + 1; j < m; ++j) {
          if (!h[j]) continue;
          auto [it, fresh] = pair_min.emplace(std::make_pair(i, j), s.size());
          if (!fresh) it->second = std::min(it->second, s.size());
        }
      }
      if (!some) complete_min = std::min(complete_min, s.size());
      for (size_t k = 0; k < port.asserts.size(); ++k) {
        if (h[bf.rule_index(port.asserts[k].rule)] && !evaluate(port.asserts[k].property, s)) {
          assert_min[k] = std::min(assert_min[k], s.size());
        }
      }
    }
    if (!any_state) {  // contradictory invariants: every rule is dead; compared elsewhere
      ++skipped;
      continue;
    }

    VerifyOptions options;
    options.max_pairs_per_port = 1000;
    std::string error;
    std::optional<VerifyReport> report = verify_app(app, options, &error);
    ASSERT_TRUE(report) << error;
    const PortResult& pr = report->ports[0];
    ASSERT_NE(pr.verdict, Verdict::Unknown) << pr.unknown_reason;
    std::string context = "port " + std::to_string(compared) + "\n" + model::to_app_json(app);

    std::map<std::pair<size_t, size_t>, size_t> found_pairs;
    std::set<size_t> dead;
    bool complete_found = false;
    std::vector<bool> assert_found(port.asserts.size(), false);
    for (const Finding& f : pr.findings) {
      ASSERT_NE(f.check, kCheckInternal) << f.message << context;
      std::set<std::string> s;
      if (f.counterexample) s = as_set(f.counterexample->present);
      if (f.counterexample) {
        ASSERT_TRUE(bf.domain(s)) << context;
      }
      if (f.check == kCheckExclusive) {
        size_t i = bf.rule_index(f.rules[0]), j = bf.rule_index(f.rules[1]);
        ASSERT_TRUE(bf.holds(i, s) && bf.holds(j, s)) << "invalid counterexample\n" << context;
        ASSERT_TRUE(pair_min.count({i, j})) << context;
        EXPECT_EQ(s.size(), pair_min[std::make_pair(i, j)]) << "not minimal\n" << context;
        found_pairs[{i, j}] = s.size();
      } else if (f.check == kCheckDead) {
        dead.insert(bf.rule_index(f.rules[0]));
      } else if (f.check == kCheckComplete) {
        complete_found = true;
        for (size_t i = 0; i < m; ++i) ASSERT_FALSE(bf.holds(i, s)) << context;
        EXPECT_EQ(s.size(), complete_min) << "not minimal\n" << context;
      } else if (f.check == kCheckAssert) {
        size_t k = 0;
        while (k < port.asserts.size() && port.asserts[k].rule != f.rules[0]) ++k;
        // Several asserts may name the same rule: match the one this state refutes.
        for (size_t q = 0; q < port.asserts.size(); ++q) {
          if (port.asserts[q].rule == f.rules[0] && !assert_found[q] &&
              !evaluate(port.asserts[q].property, s) && assert_min[q] == s.size()) {
            k = q;
            break;
          }
        }
        ASSERT_LT(k, port.asserts.size());
        ASSERT_TRUE(bf.holds(bf.rule_index(f.rules[0]), s)) << context;
        ASSERT_FALSE(evaluate(port.asserts[k].property, s)) << context;
        EXPECT_EQ(s.size(), assert_min[k]) << "not minimal\n" << context;
        assert_found[k] = true;
      }
    }
    EXPECT_EQ(found_pairs.size(), pair_min.size()) << context;
    EXPECT_EQ(pr.overlapping_pairs, static_cast<int>(pair_min.size())) << context;
    for (size_t i = 0; i < m; ++i) EXPECT_EQ(dead.count(i) > 0, !can_hold[i]) << context;
    if (port.complete) {
      EXPECT_EQ(complete_found, complete_min != none) << context;
    }
    for (size_t k = 0; k < port.asserts.size(); ++k) {
      EXPECT_EQ(assert_found[k], assert_min[k] != none) << "assert " << k << "\n" << context;
    }
    bool brute_refuted =
        !pair_min.empty() || (port.complete && complete_min != none) ||
        std::any_of(assert_min.begin(), assert_min.end(), [&](size_t v) { return v != none; });
    bool has_other_error = false;  // unfed / ownership are structural, not brute-forced here
    for (const Finding& f : pr.findings) {
      has_other_error |=
          f.severity == Severity::Error && (f.check == kCheckUnfed || f.check == kCheckOwnership);
    }
    if (!has_other_error) {
      EXPECT_EQ(pr.verdict == Verdict::Refuted, brute_refuted) << context;
    }
    (brute_refuted ? refuted : proved)++;
    ++compared;
    if (::testing::Test::HasFailure()) return;
  }
  // The generator must exercise both outcomes, or the comparison proves little.
  EXPECT_GT(refuted, kPorts / 10);
  EXPECT_GT(proved, kPorts / 10);
  EXPECT_LT(skipped, kPorts / 5);
  std::printf("compared %d ports: %d refuted, %d proved, %d skipped (no state)\n", compared,
              refuted, proved, skipped);
}

}  // namespace
}  // namespace arbc::verify
