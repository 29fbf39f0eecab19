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
  return model::temporal_property_text(p);
}

}  // namespace arbc::verify::temporal
