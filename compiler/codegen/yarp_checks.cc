#include "compiler/codegen/yarp_checks.h"

#include "compiler/codegen/lua_expr.h"
#include "compiler/codegen/lua_text.h"
#include "compiler/codegen/lua_writer.h"
#include "core/app_model.h"
#include "core/count_text.h"

namespace arbc::codegen {

namespace {

// The list bound: the longest list anywhere in the message, as the embedded runtime measures it
// (runtime/message_path.cc), read through the message's type descriptor.
void bound_lua(const model::Connection& rule, const std::string& who, LuaWriter& out) {
  std::string bound = std::to_string(rule.list_bound);
  out.line("-- The proof of '" + rule.name + "' covers lists of at most " + bound +
           " elements (arbc verify --list-bound): a longer one is dropped, as the embedded");
  out.line(
      "-- runtime drops it (bad-value); said the first time, counted when the connection goes.");
  out.line("local arbc_bound_drops = 0");
  out.line("local function arbc_longest_list(v, t)");
  out.line("  local n = 0");
  out.line("  if t.kind == \"list\" then");
  out.line("    n = #v");
  out.line("    for _, e in ipairs(v) do n = math.max(n, arbc_longest_list(e, t.element)) end");
  out.line("  elseif t.kind == \"record\" then");
  out.line("    for _, f in ipairs(t.order) do");
  out.line("      n = math.max(n, arbc_longest_list(v[f], t.fields[f]))");
  out.line("    end");
  out.line("  end");
  out.line("  return n");
  out.line("end");
  out.line("local function arbc_over_bound(msg)");
  out.line("  local n = arbc_longest_list(msg, arbc_in_type)");
  out.line("  if n <= " + bound + " then return false end");
  out.line("  arbc_bound_drops = arbc_bound_drops + 1");
  out.line("  if arbc_bound_drops == 1 then");
  out.line("    io.stderr:write(" +
           lua_string(who + ": runtime check: dropped a message with a list of ") + " .. n .. " +
           lua_string(" elements; the proof of '" + rule.name + "' covers at most " + bound +
                      " (bad-value; later ones are counted)\n") +
           ")");
  out.line("  end");
  out.line("  return true");
  out.line("end");
  out.blank();
}

// Each assert over `emitted` as a Lua predicate generated from the IR the proof encodes, judged
// on each delivered value.
void claims_lua(const std::vector<const model::Assertion*>& asserts, const model::Connection& rule,
                const std::string& who, LuaWriter& out) {
  LuaExprTranslator tr("emitted");
  model::BodyExpr message;
  message.op = model::BodyExpr::Op::Message;
  const std::string param = tr.expr(message);
  LuaWriter checks;
  for (const model::Assertion* a : asserts) {
    std::string text = model::assertion_text(rule.destination, *a);
    checks.line("{ text = " + lua_string(text) + ", broken = 0,", a->loc.line);
    checks.line("  holds = function(" + param + ") return " + tr.expr(*a->emitted) + " end },",
                a->loc.line);
  }
  out.line("-- The asserts over `emitted` of '" + rule.name +
           "', generated from the IR the proof encodes (as claims.lua");
  out.line("-- is for the embedded runtime), judged on each value it delivers: a breach is said");
  out.line("-- the first time and counted when the connection goes.");
  out.line("local arbc_claims = {}");
  out.line("do");
  LuaWriter body;
  write_helpers_and_constants(tr, body);
  body.line("arbc_claims = {");
  body.indent();
  body.append(checks);
  body.dedent();
  body.line("}");
  out.indent();
  out.append(body);
  out.dedent();
  out.line("end");
  out.line("local function arbc_check_claims(value, bottle)");
  out.line("  for _, c in ipairs(arbc_claims) do");
  out.line("    local ok, holds = pcall(c.holds, value)");
  out.line("    if not ok or holds ~= true then");
  out.line("      c.broken = c.broken + 1");
  out.line("      if c.broken == 1 then");
  out.line("        io.stderr:write(" + lua_string(who + ": runtime check: ") + " .. c.text .. " +
           lua_string(" broken: '" + rule.name + "' delivered `") +
           " .. bottle:toString() .. \"`, for which it is \" .. (ok and \"false\" or "
           "\"undefined\") .. \" (later breaches are counted)\\n\")");
  out.line("      end");
  out.line("    end");
  out.line("  end");
  out.line("end");
  out.blank();
}

}  // namespace

std::vector<const model::Assertion*> yarp_checked_asserts(const model::App& app,
                                                          const model::Connection& rule) {
  std::vector<const model::Assertion*> out;
  const model::ArbitratedPort* p = app.find_arbitrated(rule.destination);
  if (!p) return out;
  for (const model::Assertion& a : p->asserts)
    if (a.emitted && a.rule == rule.name) out.push_back(&a);
  return out;
}

std::string yarp_checks_lua(const model::App& app, const model::Connection& rule,
                            const std::string& who) {
  std::vector<const model::Assertion*> asserts = yarp_checked_asserts(app, rule);
  if (asserts.empty() && rule.list_bound <= 0) return "";
  LuaWriter out;
  out.line("-- ---- Runtime checks (docs/yarp.md#runtime-checks)");
  if (rule.list_bound > 0) bound_lua(rule, who, out);
  if (!asserts.empty()) claims_lua(asserts, rule, who, out);
  out.line("local function arbc_checks_destroy()");
  if (rule.list_bound > 0)
    out.line("  if arbc_bound_drops > 0 then io.stderr:write(" +
             lua_string(who + ": runtime check: ") + " .. arbc_bound_drops .. " +
             lua_string(" messages dropped with a list longer than the proof covers\n") + ") end");
  if (!asserts.empty()) {
    out.line("  for _, c in ipairs(arbc_claims) do");
    out.line("    if c.broken > 0 then io.stderr:write(" + lua_string(who + ": runtime check: ") +
             " .. c.text .. \" broken by \" .. c.broken .. \" deliveries\\n\") end");
    out.line("  end");
  }
  out.line("end");
  out.blank();
  return out.text();
}

std::vector<std::string> yarp_unchecked(const model::App& app) {
  std::vector<std::string> out;
  size_t exclusive = 0, event_asserts = 0, resources = app.resources.size();
  for (const model::ArbitratedPort& p : app.arbitrated_ports) {
    if (!p.by_priority && p.rules.size() > 1) ++exclusive;
    for (const model::Assertion& a : p.asserts) event_asserts += a.emitted ? 0 : 1;
  }
  auto add = [&](size_t n, const char* one, const char* many) {
    if (n) out.push_back(count_of(n, one, many));
  };
  if (exclusive) out.push_back("the exclusivity of " + count_of(exclusive, "port", "ports"));
  add(event_asserts, "assert over events", "asserts over events");
  add(resources, "resource", "resources");
  add(app.temporal.size(), "property over time", "properties over time");
  add(app.exclusive_groups.size() + app.invariants.size() + app.assumptions.size() +
          app.rates.size(),
      "assumption", "assumptions");
  return out;
}

size_t yarp_checked_count(const model::App& app) {
  size_t n = 0;
  for (const model::Connection& c : app.connections) {
    if (c.kind != model::ConnectionKind::Rule) continue;
    n += yarp_checked_asserts(app, c).size() + (c.list_bound > 0 ? 1 : 0);
  }
  return n;
}

}  // namespace arbc::codegen
