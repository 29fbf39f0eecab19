#include "verify/temporal/short_bound.h"

#include "core/duration_literal.h"
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

}  // namespace arbc::verify::temporal
