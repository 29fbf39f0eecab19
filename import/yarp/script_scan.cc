// The lexical half of script_facts.h: PortMonitor calls, callbacks, and what makes a script's
// event names unknowable.
#include <map>

#include "import/yarp/script_facts.h"

namespace arbc::yarp {
namespace {

bool is_name(const LuaExpr* e, std::string_view name) {
  return e && e->kind == LuaExpr::Kind::Name && e->text == name;
}

// `PortMonitor.<key>` with a literal key: the key, else nullptr.
const std::string* port_monitor_field(const LuaExpr* e) {
  if (!e || e->kind != LuaExpr::Kind::Index || !is_name(e->items[0].get(), "PortMonitor"))
    return nullptr;
  const LuaExpr* key = e->items[1].get();
  return key->kind == LuaExpr::Kind::String ? &key->text : nullptr;
}

// Top-level functions by name (`function f`, `local function f`, `[local] f = function`).
std::map<std::string, const LuaFunction*> top_level_functions(const LuaFunction& chunk) {
  std::map<std::string, const LuaFunction*> out;
  for (const LuaStat& s : chunk.body.stats) {
    if (s.kind == LuaStat::Kind::LocalFunction) out[s.names[0]] = s.function.get();
    if (s.kind == LuaStat::Kind::Function && s.targets[0]->kind == LuaExpr::Kind::Name)
      out[s.targets[0]->text] = s.function.get();
    bool local = s.kind == LuaStat::Kind::Local, assign = s.kind == LuaStat::Kind::Assign;
    if (!local && !assign) continue;
    for (size_t i = 0; i < s.exprs.size(); ++i) {
      if (s.exprs[i]->kind != LuaExpr::Kind::Function) continue;
      if (local && i < s.names.size()) out[s.names[i]] = s.exprs[i]->function.get();
      if (assign && i < s.targets.size() && s.targets[i]->kind == LuaExpr::Kind::Name)
        out[s.targets[i]->text] = s.exprs[i]->function.get();
    }
  }
  return out;
}

// All PortMonitor.<name> = function assignments at the top level; the last one wins, as when
// the chunk runs.
std::map<std::string, const LuaFunction*> top_level_callbacks(const LuaFunction& chunk) {
  std::map<std::string, const LuaFunction*> named = top_level_functions(chunk), out;
  for (const LuaStat& s : chunk.body.stats) {
    if (s.kind == LuaStat::Kind::Function) {
      if (const std::string* k = port_monitor_field(s.targets[0].get())) out[*k] = s.function.get();
    }
    if (s.kind != LuaStat::Kind::Assign) continue;
    for (size_t i = 0; i < s.targets.size() && i < s.exprs.size(); ++i) {
      const std::string* k = port_monitor_field(s.targets[i].get());
      if (!k) continue;
      const LuaExpr& v = *s.exprs[i];
      if (v.kind == LuaExpr::Kind::Function) {
        out[*k] = v.function.get();
      } else if (v.kind == LuaExpr::Kind::Name && named.count(v.text)) {
        out[*k] = named[v.text];
      } else {
        out[*k] = nullptr;  // assigned something arbc does not follow
      }
    }
  }
  return out;
}

std::optional<double> literal_number(const LuaExpr* e) {
  if (!e) return std::nullopt;
  if (e->kind == LuaExpr::Kind::Number) return e->number;
  if (e->kind == LuaExpr::Kind::Unary && e->text == "-" &&
      e->items[0]->kind == LuaExpr::Kind::Number)
    return -e->items[0]->number;
  return std::nullopt;
}

class Scanner {
 public:
  // `assigned` names every variable assigned anywhere in the chunk (from a first pass).
  Scanner(const LuaFunction& chunk, ScriptFacts& facts, std::set<std::string> assigned)
      : facts_(facts), all_assigned_(std::move(assigned)) {
    for (const auto& [name, fn] : top_level_callbacks(chunk)) {
      if (fn) {
        callback_of_[fn] = name;
        facts_.callbacks.insert(name);
      } else {
        make_opaque("PortMonitor." + name + " is assigned something other than a function", 0);
      }
    }
    find_constants(chunk);
  }

  void function(const LuaFunction& f, const std::string& context) {
    std::string saved = context_;
    auto it = callback_of_.find(&f);
    context_ = it != callback_of_.end() ? it->second : context;
    block(f.body);
    context_ = saved;
  }

 private:
  void make_opaque(const std::string& why, int line, const std::string& token = "PortMonitor",
                   bool names_only = false) {
    facts_.opaque_names_only = (facts_.opaque ? facts_.opaque_names_only : true) && names_only;
    if (facts_.opaque) return;
    facts_.opaque = true;
    facts_.opaque_reason = why;
    facts_.opaque_line = line;
    facts_.opaque_token = token;
  }

  // `local NAME = <number>` at the top level, never assigned again: a known lifetime.
  void find_constants(const LuaFunction& chunk) {
    for (const LuaStat& s : chunk.body.stats) {
      if (s.kind != LuaStat::Kind::Local) continue;
      for (size_t i = 0; i < s.names.size() && i < s.exprs.size(); ++i) {
        if (auto v = literal_number(s.exprs[i].get())) constants_[s.names[i]] = *v;
      }
    }
  }
  std::optional<double> number_of(const LuaExpr* e) const {
    if (auto v = literal_number(e)) return v;
    if (e && e->kind == LuaExpr::Kind::Name && constants_.count(e->text) &&
        !all_assigned_.count(e->text))
      return constants_.at(e->text);
    return std::nullopt;
  }

  void block(const LuaBlock& b) {
    for (const LuaStat& s : b.stats) stat(s);
  }

  void stat(const LuaStat& s) {
    for (const LuaExprPtr& t : s.targets) {
      if (t->kind == LuaExpr::Kind::Name) assigned_.insert(t->text);
      if (const std::string* k = port_monitor_field(t.get());
          k && (*k == "setEvent" || *k == "unsetEvent"))
        make_opaque("the script replaces PortMonitor." + *k, s.line);
      // Assignments to PortMonitor.<callback> are fine; visit only the rest of the target.
      if (port_monitor_field(t.get())) continue;
      expr(t.get());
    }
    for (const LuaExprPtr& e : s.exprs) expr(e.get());
    for (const LuaBlock& b : s.blocks) block(b);
    if (s.function) function(*s.function, "(helper)");
  }

  void call(const LuaExpr& e, const std::string& fn) {
    MonitorCall c;
    c.function = fn;
    c.line = e.line;
    c.callback = context_;
    c.node = &e;
    const LuaExpr* a0 = e.items.size() > 1 ? e.items[1].get() : nullptr;
    const LuaExpr* a1 = e.items.size() > 2 ? e.items[2].get() : nullptr;
    if (a0 && a0->kind == LuaExpr::Kind::String) c.text = a0->text;
    if (fn == "setTrigInterval") c.number = number_of(a0);
    if (fn == "setEvent") {
      c.has_second = a1 != nullptr;
      c.number = number_of(a1);
    }
    if ((fn == "setEvent" || fn == "unsetEvent") && !c.text) {
      make_opaque("PortMonitor." + fn + " is called with a name that is not a string literal",
                  e.line, fn, true);
    }
    facts_.calls.push_back(std::move(c));
  }

  void expr(const LuaExpr* e) {
    if (!e) return;
    switch (e->kind) {
      case LuaExpr::Kind::Name:
        if (e->text == "PortMonitor") make_opaque("PortMonitor is used as a value", e->line);
        if (e->text == "_G" || e->text == "_ENV" || e->text == "debug")
          make_opaque("the script reaches globals through " + e->text, e->line, e->text);
        return;
      case LuaExpr::Kind::Index:
        if (is_name(e->items[0].get(), "PortMonitor")) {
          if (e->items[1]->kind != LuaExpr::Kind::String)
            make_opaque("PortMonitor is indexed with a computed key", e->line);
          // Not the callee of a call (those are visited in the Call case): `local setEvent =
          // PortMonitor.setEvent`, the paper's unqualified style, calls it under another name.
          const std::string& key = e->items[1]->text;
          if (e->items[1]->kind == LuaExpr::Kind::String &&
              (key == "setEvent" || key == "unsetEvent"))
            make_opaque("PortMonitor." + key + " is used as a value, so its calls are not seen",
                        e->line, "PortMonitor." + key);
          expr(e->items[1].get());
          return;
        }
        break;
      case LuaExpr::Kind::Call: {
        const LuaExpr* callee = e->items[0].get();
        const std::string* k = port_monitor_field(callee);
        if (k && (*k == "setEvent" || *k == "unsetEvent" || *k == "setConstraint" ||
                  *k == "setTrigInterval"))
          call(*e, *k);
        if (callee->kind == LuaExpr::Kind::Name) dynamic_code(*e);
        if (k) {
          // PortMonitor.f(...): the callee is not a use of PortMonitor.f as a value.
          for (size_t i = 1; i < e->items.size(); ++i) expr(e->items[i].get());
          return;
        }
        break;
      }
      case LuaExpr::Kind::Function:
        function(*e->function, "(helper)");
        return;
      default:
        break;
    }
    for (const LuaExprPtr& item : e->items) expr(item.get());
  }

  // load, dofile, require of anything but "yarp": code arbc cannot see may set events.
  void dynamic_code(const LuaExpr& call) {
    const std::string& n = call.items[0]->text;
    bool yarp = n == "require" && call.items.size() == 2 &&
                call.items[1]->kind == LuaExpr::Kind::String && call.items[1]->text == "yarp";
    if (yarp) return;
    if (n == "load" || n == "loadstring" || n == "loadfile" || n == "dofile" || n == "require")
      make_opaque("the script runs code arbc cannot see (" + n + ")", call.line, n);
  }

  ScriptFacts& facts_;
  std::map<const LuaFunction*, std::string> callback_of_;
  std::map<std::string, double> constants_;
  std::set<std::string> all_assigned_;

 public:
  std::set<std::string> assigned_;  // filled by the walk

 private:
  std::string context_;
};

}  // namespace

std::set<std::string> ScriptFacts::sets() const {
  std::set<std::string> out;
  for (const MonitorCall& c : calls) {
    if (c.function == "setEvent" && c.text) out.insert(*c.text);
  }
  return out;
}

std::set<std::string> ScriptFacts::unsets() const {
  std::set<std::string> out;
  for (const MonitorCall& c : calls) {
    if (c.function == "unsetEvent" && c.text) out.insert(*c.text);
  }
  return out;
}

const LuaFunction* find_callback(const LuaFunction& chunk, const std::string& name) {
  auto all = top_level_callbacks(chunk);
  auto it = all.find(name);
  return it == all.end() ? nullptr : it->second;
}

ScriptFacts analyse_script(const LuaFunction& chunk) {
  ScriptFacts scratch, facts;
  Scanner first(chunk, scratch, {});
  first.function(chunk, "");
  Scanner(chunk, facts, std::move(first.assigned_)).function(chunk, "");
  analyse_paths(chunk, facts);
  return facts;
}

}  // namespace arbc::yarp
