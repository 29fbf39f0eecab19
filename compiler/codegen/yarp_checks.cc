#include "compiler/codegen/yarp_checks.h"

#include "compiler/codegen/lua_expr.h"
#include "compiler/codegen/lua_text.h"
#include "compiler/codegen/lua_writer.h"
#include "core/app_model.h"
#include "core/count_text.h"
#include "core/duration_literal.h"
#include "core/instant.h"

namespace arbc::codegen {

namespace {

// The body of a check's `if` when it is broken: count the breach in `var`.broken and say the
// first one on stderr (`said`: a Lua expression), indented for a check inside a `for` loop.
void count_breach(const std::string& var, const std::string& said, LuaWriter& out) {
  out.line("      " + var + ".broken = " + var + ".broken + 1");
  out.line("      if " + var + ".broken == 1 then");
  out.line("        io.stderr:write(" + said + ")");
  out.line("      end");
}

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
  count_breach("c",
               lua_string(who + ": runtime check: ") + " .. c.text .. " +
                   lua_string(" broken: '" + rule.name + "' delivered `") +
                   " .. bottle:toString() .. \"`, for which it is \" .. (ok and \"false\" or "
                   "\"undefined\") .. \" (later breaches are counted)\\n\"",
               out);
  out.line("    end");
  out.line("  end");
  out.line("end");
  out.blank();
}

// `never two RULE within D` of the rule itself: its monitor sees each of its deliveries (update
// runs on what YARP selected), so two less than D apart break it, as runtime/property_watch.h
// judges a spacing.
void spacings_lua(const std::vector<const model::TemporalProperty*>& spacings,
                  const model::Connection& rule, const std::string& who, LuaWriter& out) {
  out.line("-- Properties over time of '" + rule.name +
           "' alone, judged at each of its deliveries: a breach is");
  out.line("-- said the first time and counted when the connection goes.");
  out.line("local arbc_spacings = {");
  for (const model::TemporalProperty* p : spacings)
    out.line("  { text = " + lua_string(model::temporal_property_text(*p)) +
                 ", window = " + lua_float(seconds_of(p->window)) + ", broken = 0 },",
             p->loc.line);
  out.line("}");
  out.line("local arbc_last_delivered = nil");
  out.line("local function arbc_check_spacings()");
  out.line("  local now = yarp.now()");
  out.line("  for _, s in ipairs(arbc_spacings) do");
  out.line("    if arbc_last_delivered ~= nil and now < arbc_last_delivered + s.window then");
  count_breach("s",
               lua_string(who + ": runtime check: ") + " .. s.text .. " +
                   lua_string(" broken: '" + rule.name + "' delivered twice ") +
                   " .. string.format(\"%.3f\", now - arbc_last_delivered) .. " +
                   lua_string("s apart (later breaches are counted)\n"),
               out);
  out.line("    end");
  out.line("  end");
  out.line("  arbc_last_delivered = now");
  out.line("end");
  out.blank();
}

// `given M.p every D` of the rule's source: its monitor sees every message of M.p (accept runs
// on each), so a gap longer than D breaks it, as runtime/claim_watch.h judges a rate. A source
// that stops for good is not said when the connection goes (that is how a source's end looks).
void rates_lua(const std::vector<const model::SourceRate*>& rates, const std::string& who,
               LuaWriter& out) {
  out.line("-- The rate the proof assumed of the source, judged at each message it sends: a");
  out.line("-- breach is said the first time and counted when the connection goes.");
  out.line("local arbc_rates = {");
  for (const model::SourceRate* r : rates)
    out.line(
        "  { text = " + lua_string("given " + r->port + " every " + duration_literal(r->period)) +
            ", port = " + lua_string(r->port) + ", period = " + lua_float(seconds_of(r->period)) +
            ", broken = 0 },",
        r->loc.line);
  out.line("}");
  out.line("local arbc_last_heard = nil");
  out.line("local function arbc_check_rates()");
  out.line("  local now = yarp.now()");
  out.line("  for _, r in ipairs(arbc_rates) do");
  out.line("    if arbc_last_heard ~= nil and now > arbc_last_heard + r.period then");
  count_breach("r",
               lua_string(who + ": runtime check: assumption ") +
                   " .. r.text .. \" broken: nothing from \" .. r.port .. \" for \" .. "
                   "string.format(\"%.3f\", now - arbc_last_heard) .. " +
                   lua_string("s (later breaches are counted)\n"),
               out);
  out.line("    end");
  out.line("  end");
  out.line("  arbc_last_heard = now");
  out.line("end");
  out.blank();
}

// The destroy function: each check's count, when not zero.
void destroy_lua(const model::Connection& rule, bool asserts, bool spacings, bool rates,
                 const std::string& who, LuaWriter& out) {
  std::string prefix = lua_string(who + ": runtime check: ");
  out.line("local function arbc_checks_destroy()");
  if (rule.list_bound > 0)
    out.line("  if arbc_bound_drops > 0 then io.stderr:write(" + prefix +
             " .. arbc_bound_drops .. " +
             lua_string(" messages dropped with a list longer than the proof covers\n") + ") end");
  auto counts = [&](const char* list, const char* what) {
    out.line(std::string("  for _, c in ipairs(") + list + ") do");
    out.line("    if c.broken > 0 then io.stderr:write(" + prefix + " .. c.text .. " +
             lua_string(std::string(" broken by ")) + " .. c.broken .. " +
             lua_string(std::string(" ") + what + "\n") + ") end");
    out.line("  end");
  };
  if (asserts) counts("arbc_claims", "deliveries");
  if (spacings) counts("arbc_spacings", "deliveries");
  if (rates) {  // an assumption, as the embedded runtime names it
    prefix = lua_string(who + ": runtime check: assumption ");
    counts("arbc_rates", "gaps");
  }
  out.line("end");
  out.blank();
}

}  // namespace

std::vector<const model::TemporalProperty*> yarp_checked_spacings(const model::App& app,
                                                                  const model::Connection& rule) {
  std::vector<const model::TemporalProperty*> out;
  for (const model::TemporalProperty& p : app.temporal)
    if (p.kind == model::TemporalProperty::Kind::Spacing && p.other.empty() &&
        p.rule == rule.name && p.port == rule.destination)
      out.push_back(&p);
  return out;
}

std::vector<const model::SourceRate*> yarp_checked_rates(const model::App& app,
                                                         const model::Connection& rule) {
  std::vector<const model::SourceRate*> out;
  if (rule.kind != model::ConnectionKind::Rule) return out;
  for (const model::SourceRate& r : app.rates)
    if (r.port == rule.source) out.push_back(&r);
  if (out.empty()) return out;  // most rules: no scan of the connections
  // The first rule of the source watches (one report per breach); the first connection of a
  // (source, destination) pair that is not a feed is the one that delivers (yarp_names.h).
  for (const model::Connection& c : app.connections) {
    if (c.source != rule.source || c.kind == model::ConnectionKind::Feed) continue;
    if (&c != &rule) out.clear();
    break;
  }
  return out;
}

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
  std::vector<const model::TemporalProperty*> spacings = yarp_checked_spacings(app, rule);
  std::vector<const model::SourceRate*> rates = yarp_checked_rates(app, rule);
  if (asserts.empty() && spacings.empty() && rates.empty() && rule.list_bound <= 0) return "";
  LuaWriter out;
  out.line("-- ---- Runtime checks (docs/yarp.md#runtime-checks)");
  if (rule.list_bound > 0) bound_lua(rule, who, out);
  if (!asserts.empty()) claims_lua(asserts, rule, who, out);
  if (!spacings.empty()) spacings_lua(spacings, rule, who, out);
  if (!rates.empty()) rates_lua(rates, who, out);
  destroy_lua(rule, !asserts.empty(), !spacings.empty(), !rates.empty(), who, out);
  return out.text();
}

std::vector<std::string> yarp_unchecked(const model::App& app) {
  std::vector<std::string> out;
  size_t exclusive = 0, event_asserts = 0, resources = app.resources.size();
  size_t spacings = 0, rates = 0;  // checked by a monitor
  for (const model::Connection& c : app.connections) {
    spacings += yarp_checked_spacings(app, c).size();
    rates += yarp_checked_rates(app, c).size();
  }
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
  add(app.temporal.size() - spacings, "property over time", "properties over time");
  add(app.exclusive_groups.size() + app.invariants.size() + app.assumptions.size() +
          app.rates.size() - rates,
      "assumption", "assumptions");
  return out;
}

std::vector<std::string> yarp_checked(const model::App& app) {
  size_t asserts = 0, bounds = 0, spacings = 0, rates = 0;
  for (const model::Connection& c : app.connections) {
    if (c.kind != model::ConnectionKind::Rule) continue;
    asserts += yarp_checked_asserts(app, c).size();
    bounds += c.list_bound > 0 ? 1 : 0;
    spacings += yarp_checked_spacings(app, c).size();
    rates += yarp_checked_rates(app, c).size();
  }
  std::vector<std::string> out;
  auto add = [&](size_t n, const char* one, const char* many) {
    if (n) out.push_back(count_of(n, one, many));
  };
  add(asserts, "assert over `emitted`", "asserts over `emitted`");
  add(bounds, "list bound", "list bounds");
  add(spacings, "spacing of one rule", "spacings of one rule");
  add(rates, "source rate", "source rates");
  return out;
}

}  // namespace arbc::codegen
