#include "verify/temporal/property.h"

#include "core/duration_literal.h"
#include "core/time_text.h"
#include "verify/temporal/absence.h"
#include "verify/temporal/precedence.h"
#include "verify/temporal/response.h"
#include "verify/temporal/spacing.h"
#include "verify/temporal/stability.h"

namespace arbc::verify::temporal {

std::optional<TemporalResult> check_property(const model::App& app,
                                             const model::TemporalProperty& p, int bound,
                                             z3::context& ctx, DataQuery* data,
                                             std::chrono::steady_clock::time_point deadline,
                                             std::string* err, bool faithful) {
  switch (p.kind) {
    case model::TemporalProperty::Kind::Spacing:
      return check_spacing(app, p, bound, ctx, data, deadline, err, faithful);
    case model::TemporalProperty::Kind::Absence:
      return check_absence(app, p, bound, ctx, data, deadline, err, faithful);
    case model::TemporalProperty::Kind::Precedence:
      return check_precedence(app, p, bound, ctx, data, deadline, err, faithful);
    case model::TemporalProperty::Kind::Response:
      return check_response(app, p, bound, ctx, data, deadline, err, faithful);
    case model::TemporalProperty::Kind::Stability:
      return check_stability(app, p, bound, ctx, data, deadline, err, faithful);
  }
  *err = "unknown kind of property over time";
  return std::nullopt;
}

std::string property_words(const model::TemporalProperty& p) {
  switch (p.kind) {
    case model::TemporalProperty::Kind::Spacing:
      if (!p.other.empty())
        return "never " + p.rule + " within " + duration_literal(p.window) + " after " + p.other;
      return "never two " + p.rule + " within " + duration_literal(p.window);
    case model::TemporalProperty::Kind::Absence:
      return "never " + p.rule + " while " + p.event;
    case model::TemporalProperty::Kind::Precedence:
      return "only " + p.rule + " after " + p.other;
    case model::TemporalProperty::Kind::Response: {
      std::string words = "after " + (p.event.empty() ? p.other : p.event) +
                          (p.stops ? " stops, " : ", ") + (p.rule.empty() ? p.port : p.rule) +
                          " within " + duration_literal(p.window);
      if (p.condition.op != Constraint::Op::True) words += " while " + p.condition.to_string();
      return words;
    }
    case model::TemporalProperty::Kind::Stability:
      return "stable " + p.port + " for " + duration_literal(p.window);
  }
  return p.rule;
}

}  // namespace arbc::verify::temporal
