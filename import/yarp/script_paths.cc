// The path half of script_facts.h. Each callback is run abstractly: the state is, per event
// the script names, what the callback has done to it so far (nothing, set, set with a lifetime
// that may already be over, unset, or unknown after a call into script code). Conditions are
// not evaluated, so every branch is taken: more paths only remove facts, so the facts stay
// sound. A statement that may raise ends a path with an error (YARP then drops the message and
// keeps the events set so far).
#include <algorithm>
#include <cstring>
#include <map>

#include "import/yarp/script_facts.h"

namespace arbc::yarp {
namespace {

enum Effect : uint8_t { kSame, kSet, kSetMaybe, kUnset, kHavoc };
enum class Exit : uint8_t { Normal, Break, Accept, Reject, Maybe, Error };

struct Outcome {
  Exit exit = Exit::Normal;
  std::vector<uint8_t> effects;
  auto operator<=>(const Outcome&) const = default;
};
using Outcomes = std::set<Outcome>;

constexpr size_t kMaxOutcomes = 20000;
constexpr size_t kMaxEvents = 64;

const char* const kLibraryTables[] = {"string", "math", "table",     "utf8",
                                      "os",     "io",   "coroutine", "yarp"};
const char* const kLibraryFunctions[] = {
    "print",  "tostring", "tonumber", "type",         "ipairs",       "pairs",         "assert",
    "error",  "rawequal", "rawlen",   "rawget",       "rawset",       "select",        "next",
    "unpack", "pcall",    "xpcall",   "getmetatable", "setmetatable", "collectgarbage"};

template <size_t N>
bool one_of(const std::string& s, const char* const (&list)[N]) {
  return std::any_of(std::begin(list), std::end(list), [&](const char* x) { return s == x; });
}

bool is_event_call(const LuaExpr& e) {
  if (e.kind != LuaExpr::Kind::Call) return false;
  const LuaExpr& c = *e.items[0];
  return c.kind == LuaExpr::Kind::Index && c.items[0]->kind == LuaExpr::Kind::Name &&
         c.items[0]->text == "PortMonitor" && c.items[1]->kind == LuaExpr::Kind::String &&
         (c.items[1]->text == "setEvent" || c.items[1]->text == "unsetEvent");
}

// Names and field names the script binds to functions, anywhere.
struct ScriptFunctions {
  std::set<std::string> names, fields;
  std::set<std::string> called_callbacks;  // PortMonitor.<name>(...) calls in the script
  bool uses_metatables = false;

  void block(const LuaBlock& b) {
    for (const LuaStat& s : b.stats) stat(s);
  }
  void stat(const LuaStat& s) {
    if (s.kind == LuaStat::Kind::LocalFunction) names.insert(s.names[0]);
    if (s.kind == LuaStat::Kind::Function) bind(*s.targets[0]);
    for (size_t i = 0; i < s.exprs.size(); ++i) {
      if (s.exprs[i]->kind == LuaExpr::Kind::Function) {
        if (s.kind == LuaStat::Kind::Local && i < s.names.size()) names.insert(s.names[i]);
        if (s.kind == LuaStat::Kind::Assign && i < s.targets.size()) bind(*s.targets[i]);
      }
    }
    for (const LuaExprPtr& e : s.targets) expr(*e);
    for (const LuaExprPtr& e : s.exprs) expr(*e);
    for (const LuaBlock& b : s.blocks) block(b);
    if (s.function) block(s.function->body);
  }
  void bind(const LuaExpr& target) {
    if (target.kind == LuaExpr::Kind::Name) names.insert(target.text);
    if (target.kind == LuaExpr::Kind::Index && target.items[1]->kind == LuaExpr::Kind::String)
      fields.insert(target.items[1]->text);
  }
  void expr(const LuaExpr& e) {
    if (e.kind == LuaExpr::Kind::Name && e.text == "setmetatable") uses_metatables = true;
    if (e.kind == LuaExpr::Kind::Call) {
      const LuaExpr& c = *e.items[0];
      if (c.kind == LuaExpr::Kind::Index && c.items[0]->kind == LuaExpr::Kind::Name &&
          c.items[0]->text == "PortMonitor" && c.items[1]->kind == LuaExpr::Kind::String)
        called_callbacks.insert(c.items[1]->text);
    }
    if (e.kind == LuaExpr::Kind::Table) {
      // { key = function ... end }: the key is a function field.
      for (size_t i = 0; i + 1 < e.items.size(); ++i) {
        if (e.items[i]->kind == LuaExpr::Kind::String &&
            e.items[i + 1]->kind == LuaExpr::Kind::Function)
          fields.insert(e.items[i]->text);
      }
    }
    if (e.kind == LuaExpr::Kind::Function) block(e.function->body);
    for (const LuaExprPtr& i : e.items) expr(*i);
  }
};

class PathAnalysis {
 public:
  PathAnalysis(const LuaFunction& chunk, const ScriptFacts& facts) : facts_(facts) {
    for (const MonitorCall& c : facts.calls) {
      if ((c.function == "setEvent" || c.function == "unsetEvent") && c.text &&
          !index_.count(*c.text)) {
        index_[*c.text] = events_.size();
        events_.push_back(*c.text);
      }
    }
    functions_.block(chunk.body);
    // Calls into script code may touch what helpers and the callbacks it calls touch.
    for (const MonitorCall& c : facts.calls) {
      if (c.text && index_.count(*c.text) &&
          (c.callback == "(helper)" || functions_.called_callbacks.count(c.callback)))
        havoc_.insert(index_[*c.text]);
    }
  }

  bool failed() const { return !reason_.empty(); }
  const std::string& reason() const { return reason_; }
  const std::vector<std::string>& events() const { return events_; }
  bool too_many_events() const { return events_.size() > kMaxEvents; }
  bool metatables_with_helpers() const { return functions_.uses_metatables && !havoc_.empty(); }

  // All outcomes of running `f` once, from a state where it has done nothing yet.
  Outcomes run(const LuaFunction& f) {
    Outcome start{Exit::Normal, std::vector<uint8_t>(events_.size(), kSame)};
    Outcomes out = block(f.body, {start});
    Outcomes final;
    for (Outcome o : out) {
      if (o.exit == Exit::Normal || o.exit == Exit::Break) o.exit = Exit::Reject;  // returns nil
      final.insert(std::move(o));
    }
    return final;
  }

 private:
  void fail(const std::string& why, int line) {
    if (reason_.empty()) reason_ = "line " + std::to_string(line) + ": " + why;
  }

  Outcomes block(const LuaBlock& b, Outcomes in) {
    for (const LuaStat& s : b.stats) {
      Outcomes next;
      for (const Outcome& o : in) {
        if (o.exit != Exit::Normal) {
          next.insert(o);
        } else {
          stat(s, o.effects, next);
        }
        if (next.size() > kMaxOutcomes) fail("too many paths to follow", s.line);
        if (failed()) return {};
      }
      in = std::move(next);
    }
    return in;
  }

  void stat(const LuaStat& s, std::vector<uint8_t> eff, Outcomes& out) {
    using K = LuaStat::Kind;
    switch (s.kind) {
      case K::Call:
        if (is_event_call(*s.exprs[0])) {
          event_call(*s.exprs[0], eff);
        } else {
          eff = eval(*s.exprs[0], eff, out);
        }
        out.insert({Exit::Normal, eff});
        return;
      case K::Local:
      case K::Assign:
      case K::Function:
        for (const LuaExprPtr& t : s.targets) eff = eval_target(*t, eff, out);
        for (const LuaExprPtr& e : s.exprs) eff = eval(*e, eff, out);
        out.insert({Exit::Normal, eff});
        return;
      case K::LocalFunction:
        out.insert({Exit::Normal, eff});
        return;
      case K::Break:
        out.insert({Exit::Break, eff});
        return;
      case K::Goto:
      case K::Label:
        fail("goto and labels are not followed", s.line);
        return;
      case K::Do:
        for (const Outcome& o : block(s.blocks[0], {{Exit::Normal, eff}})) out.insert(o);
        return;
      case K::If:
        if_stat(s, eff, out);
        return;
      case K::While:
      case K::Repeat:
      case K::NumericFor:
      case K::GenericFor:
        loop(s, eff, out);
        return;
      case K::Return: {
        for (const LuaExprPtr& e : s.exprs) eff = eval(*e, eff, out);
        out.insert({return_exit(s), eff});
        return;
      }
    }
  }

  static Exit return_exit(const LuaStat& s) {
    if (s.exprs.empty()) return Exit::Reject;
    switch (s.exprs[0]->kind) {
      case LuaExpr::Kind::Nil:
      case LuaExpr::Kind::False:
        return Exit::Reject;
      case LuaExpr::Kind::True:
      case LuaExpr::Kind::Number:
      case LuaExpr::Kind::String:
      case LuaExpr::Kind::Table:
      case LuaExpr::Kind::Function:
        return Exit::Accept;  // lua_toboolean: every value but nil and false is true
      default:
        return Exit::Maybe;
    }
  }

  void if_stat(const LuaStat& s, std::vector<uint8_t> eff, Outcomes& out) {
    for (size_t i = 0; i < s.exprs.size(); ++i) {
      eff = eval(*s.exprs[i], eff, out);
      for (const Outcome& o : block(s.blocks[i], {{Exit::Normal, eff}})) out.insert(o);
    }
    if (s.blocks.size() > s.exprs.size()) {
      for (const Outcome& o : block(s.blocks.back(), {{Exit::Normal, eff}})) out.insert(o);
    } else {
      out.insert({Exit::Normal, eff});
    }
  }

  // Any loop: the body runs zero or more times; states are finite, so this reaches a fixpoint.
  void loop(const LuaStat& s, std::vector<uint8_t> eff, Outcomes& out) {
    using K = LuaStat::Kind;
    if (s.kind == K::NumericFor || s.kind == K::GenericFor) {
      for (const LuaExprPtr& e : s.exprs) eff = eval(*e, eff, out);
    }
    bool iterator_calls_script = false;
    if (s.kind == K::GenericFor) {
      for (const LuaExprPtr& e : s.exprs) iterator_calls_script |= may_call_script(*e);
    }
    // Any order will do for a set of states seen: by length, then bytes. (std::less on
    // vectors draws a false -Wstringop-overread from GCC 12 at -O3.)
    auto shorter_or_less = [](const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
      if (a.size() != b.size()) return a.size() < b.size();
      return !a.empty() && std::memcmp(a.data(), b.data(), a.size()) < 0;
    };
    std::set<std::vector<uint8_t>, decltype(shorter_or_less)> seen(shorter_or_less);
    std::vector<std::vector<uint8_t>> work{eff};
    while (!work.empty() && !failed()) {
      std::vector<uint8_t> at = std::move(work.back());
      work.pop_back();
      if (!seen.insert(at).second) continue;
      if (s.kind != K::Repeat) {
        // The test (or the iterator call) before each iteration; leaving the loop here.
        if (s.kind == K::While) at = eval(*s.exprs[0], at, out);
        if (s.kind == K::GenericFor) {
          if (iterator_calls_script) at = havoc(at);
          out.insert({Exit::Error, at});
        }
        out.insert({Exit::Normal, at});
      }
      for (const Outcome& o : block(s.blocks[0], {{Exit::Normal, at}})) {
        if (o.exit == Exit::Break) {
          out.insert({Exit::Normal, o.effects});
        } else if (o.exit != Exit::Normal) {
          out.insert(o);
        } else if (s.kind == K::Repeat) {
          std::vector<uint8_t> after = eval(*s.exprs[0], o.effects, out);
          out.insert({Exit::Normal, after});
          work.push_back(after);
        } else {
          work.push_back(o.effects);
        }
      }
      if (seen.size() > kMaxOutcomes) fail("too many paths to follow", s.line);
    }
  }

  void event_call(const LuaExpr& call, std::vector<uint8_t>& eff) {
    const std::string& fn = call.items[0]->items[1]->text;
    for (const MonitorCall& c : facts_.calls) {
      if (c.node != &call || !c.text) continue;
      size_t i = index_.at(*c.text);
      if (fn == "unsetEvent") {
        eff[i] = kUnset;
      } else {
        // Present at the decision: no lifetime, a negative one (forever), or a known positive
        // one. A lifetime of 0 or an unknown one may already be over.
        bool sure = !c.has_second || (c.number && *c.number != 0);
        eff[i] = sure ? kSet : kSetMaybe;
      }
      return;
    }
  }

  std::vector<uint8_t> havoc(std::vector<uint8_t> eff) const {
    for (size_t i : havoc_) eff[i] = kHavoc;
    return eff;
  }

  // Evaluates an expression: it may call script code (havoc) and may raise (an error exit).
  std::vector<uint8_t> eval(const LuaExpr& e, std::vector<uint8_t> eff, Outcomes& out) {
    if (contains_event_call(e))
      fail("setEvent/unsetEvent inside an expression is not followed", e.line);
    if (may_call_script(e)) eff = havoc(eff);
    if (may_raise(e)) out.insert({Exit::Error, eff});
    return eff;
  }
  std::vector<uint8_t> eval_target(const LuaExpr& t, std::vector<uint8_t> eff, Outcomes& out) {
    if (t.kind == LuaExpr::Kind::Name) return eff;
    eff = eval(t, eff, out);
    out.insert({Exit::Error, eff});  // assigning a field of a non-table raises
    return eff;
  }

  static bool contains_event_call(const LuaExpr& e) {
    if (e.kind == LuaExpr::Kind::Function) return false;
    if (is_event_call(e)) return true;
    return std::any_of(e.items.begin(), e.items.end(),
                       [](const LuaExprPtr& i) { return contains_event_call(*i); });
  }

  static bool may_raise(const LuaExpr& e) {
    using K = LuaExpr::Kind;
    switch (e.kind) {
      case K::Nil:
      case K::True:
      case K::False:
      case K::Number:
      case K::String:
      case K::Vararg:
      case K::Function:
      case K::Name:
        return false;
      case K::Table:
      case K::Paren:
        break;
      case K::Unary:
        if (e.text != "not") return true;
        break;
      case K::Binary:
        if (e.text != "and" && e.text != "or" && e.text != "==" && e.text != "~=") return true;
        break;
      default:
        return true;  // calls, indexing
    }
    return std::any_of(e.items.begin(), e.items.end(),
                       [](const LuaExprPtr& i) { return may_raise(*i); });
  }

  bool args_have_script_function(const LuaExpr& call, size_t first) const {
    for (size_t i = first; i < call.items.size(); ++i) {
      const LuaExpr& a = *call.items[i];
      if (a.kind == LuaExpr::Kind::Function) return true;
      if (a.kind == LuaExpr::Kind::Name && functions_.names.count(a.text)) return true;
    }
    return false;
  }

  // Could evaluating `e` run a function the script defines (which may touch events)?
  bool may_call_script(const LuaExpr& e) const {
    if (e.kind == LuaExpr::Kind::Function) return false;
    if (e.kind == LuaExpr::Kind::Call && !is_event_call(e) && call_may_run_script(e)) return true;
    if (e.kind == LuaExpr::Kind::Method &&
        (functions_.fields.count(e.text) || args_have_script_function(e, 1)))
      return true;
    return std::any_of(e.items.begin(), e.items.end(),
                       [&](const LuaExprPtr& i) { return may_call_script(*i); });
  }

  bool call_may_run_script(const LuaExpr& call) const {
    const LuaExpr& callee = *call.items[0];
    if (callee.kind == LuaExpr::Kind::Name) {
      if (one_of(callee.text, kLibraryFunctions) && !functions_.names.count(callee.text))
        return args_have_script_function(call, 1);
      return true;
    }
    if (callee.kind != LuaExpr::Kind::Index || callee.items[1]->kind != LuaExpr::Kind::String)
      return true;
    const LuaExpr* root = &callee;
    while (root->kind == LuaExpr::Kind::Index) root = root->items[0].get();
    const std::string& key = callee.items[1]->text;
    if (root->kind == LuaExpr::Kind::Name && root->text == "PortMonitor")
      return facts_.callbacks.count(key) > 0;
    if (root->kind == LuaExpr::Kind::Name && one_of(root->text, kLibraryTables))
      return args_have_script_function(call, 1);
    return functions_.fields.count(key) > 0 || args_have_script_function(call, 1);
  }

  const ScriptFacts& facts_;
  std::vector<std::string> events_;
  std::map<std::string, size_t> index_;
  ScriptFunctions functions_;
  std::set<size_t> havoc_;
  std::string reason_;
};

bool present_after(uint8_t e) { return e == kSet || e == kSetMaybe || e == kHavoc; }
bool safe_pair(uint8_t a, uint8_t b) {
  // From a state where not both were present: after the run, not both are present.
  if (a == kUnset || b == kUnset) return true;
  return !present_after(a) && !present_after(b);
}

// Fills facts.delivery_set from the outcomes of update (script_facts.h).
void delivery_events(const Outcomes& update, const std::vector<std::string>& events,
                     ScriptFacts& facts) {
  for (size_t i = 0; i < events.size(); ++i) {
    bool every = !update.empty();
    for (const Outcome& o : update) every = every && o.effects[i] == kSet;
    for (const MonitorCall& c : facts.calls) {
      if (!c.text || *c.text != events[i]) continue;
      bool in_update = c.callback == "update" && c.function == "setEvent";
      bool destroy_unset = c.callback == "destroy" && c.function == "unsetEvent";
      every = every && (in_update || destroy_unset) &&
              (!in_update || (c.has_second && c.number && *c.number > 0));
    }
    if (every) facts.delivery_set.insert(events[i]);
  }
}

}  // namespace

void analyse_paths(const LuaFunction& chunk, ScriptFacts& facts) {
  facts.paths_ok = false;
  if (facts.opaque && !facts.opaque_names_only) {
    facts.paths_reason = "the script's event names are not all known";
    return;
  }
  // With computed names only, the paths are followed for what accept returns (a call with a
  // computed name has no known effect); the event facts are dropped below.
  PathAnalysis analysis(chunk, facts);
  if (analysis.too_many_events()) {
    facts.paths_reason = "the script names more than 64 events";
    return;
  }
  if (analysis.metatables_with_helpers()) {
    facts.paths_reason = "the script uses metatables and sets events in helper functions";
    return;
  }
  std::map<std::string, Outcomes> runs;
  for (const std::string& cb : facts.callbacks) {
    if (const LuaFunction* f = find_callback(chunk, cb)) runs[cb] = analysis.run(*f);
    if (analysis.failed()) {
      facts.paths_reason = analysis.reason();
      return;
    }
  }
  const std::vector<std::string>& events = analysis.events();
  if (runs.count("accept")) {
    std::vector<bool> all_set(events.size(), true), all_unset(events.size(), true);
    bool accepts = false;
    for (const Outcome& o : runs["accept"]) {
      if (o.exit != Exit::Accept && o.exit != Exit::Maybe) continue;
      accepts = true;
      for (size_t i = 0; i < events.size(); ++i) {
        all_set[i] = all_set[i] && o.effects[i] == kSet;
        all_unset[i] = all_unset[i] && o.effects[i] == kUnset;
      }
    }
    facts.accept_may_accept = accepts;
    for (size_t i = 0; accepts && !facts.opaque && i < events.size(); ++i) {
      if (all_set[i]) facts.must_set.insert(events[i]);
      if (all_unset[i]) facts.must_unset.insert(events[i]);
    }
  }
  if (facts.opaque) {
    facts.paths_reason = "the script's event names are not all known";
    return;
  }
  if (runs.count("update")) delivery_events(runs["update"], events, facts);
  for (size_t a = 0; a < events.size(); ++a) {
    for (size_t b = a + 1; b < events.size(); ++b) {
      bool safe = true;
      for (const auto& [cb, outcomes] : runs) {
        for (const Outcome& o : outcomes) safe = safe && safe_pair(o.effects[a], o.effects[b]);
      }
      if (safe && facts.sets().count(events[a]) && facts.sets().count(events[b])) {
        facts.never_both.emplace_back(std::min(events[a], events[b]),
                                      std::max(events[a], events[b]));
      }
    }
  }
  std::sort(facts.never_both.begin(), facts.never_both.end());
  facts.paths_ok = true;
}

}  // namespace arbc::yarp
