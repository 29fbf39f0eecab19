#include "verify/temporal/short_bound.h"

#include "core/duration_literal.h"
#include "core/event_facts.h"
#include "core/join.h"
#include "core/time_text.h"
#include "verify/temporal/property.h"
#include "verify/temporal/rates.h"

namespace arbc::verify::temporal {

std::optional<Finding> short_bound_finding(const TemporalResult& t, bool strict) {
  if (t.outcome != TemporalResult::Outcome::HoldsToBound || t.window_bound <= t.bound)
    return std::nullopt;
  Finding f;
  f.check = kCheckTemporalBound;
  f.severity = strict ? Severity::Error : Severity::Warning;
  f.strict = strict;
  if (!t.property.rule.empty()) f.rules = {t.property.rule};
  f.loc = t.property.loc;
  f.message = "'" + property_words(t.property) + "' holds up to " + std::to_string(t.bound) +
              " messages only because no window of " + duration_literal(t.property.window) +
              " fits in a run that short: at the rates given, " + std::to_string(t.bound) +
              " messages come sooner, so the search shows nothing about it";
  std::vector<std::string> rates;
  for (const model::SourceRate& r : t.rates) rates.push_back(rate_words(r));
  f.notes.push_back({"a run in which a window closes has at least " +
                         std::to_string(t.window_bound) + " messages into " + t.property.port +
                         ", " + join(rates, ", ") + ": pass --temporal-bound " +
                         std::to_string(t.window_bound) + " or more",
                     {}});
  return f;
}

std::optional<Finding> vacuous_finding(const model::App& app, const TemporalResult& t,
                                       bool strict) {
  if (t.outcome != TemporalResult::Outcome::Vacuous) return std::nullopt;
  Finding f;
  f.check = kCheckVacuous;
  f.severity = strict ? Severity::Error : Severity::Warning;
  f.strict = strict;
  if (!t.property.rule.empty()) f.rules = {t.property.rule};
  f.loc = t.property.loc;
  const std::string& e = t.property.event;
  f.message = "'" + property_words(t.property) + "' says nothing: nothing can put " + e + " into " +
              t.property.port + "'s container, where it is read";
  std::vector<std::string> elsewhere = model::ports_holding(app, e);
  if (!elsewhere.empty()) {
    f.notes.push_back({e + " is put into the container of " + join(elsewhere) +
                           ": each arbitrated port holds its own events, so that is another fact",
                       {}});
  }
  f.notes.push_back(
      {"to read it in " + t.property.port +
           ": make it a delivery event of the port "
           "that commands it (docs/language.md#delivery-events), or an event of a stream "
           "(`events from`, a derived event), which is fed into every port that reads it",
       {}});
  return f;
}

}  // namespace arbc::verify::temporal
