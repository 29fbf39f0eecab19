// Semantic analysis of durations (`lifetime D`, `hold D`, `throttle D`, `within D`, a test's
// `at D`, ...): a literal or a constant holding one, positive, and a whole number of
// nanoseconds no longer than 100 years (docs/language.md#lexical-structure). The runtime counts
// time in nanoseconds and the proof reads each duration as that count (core/instant.h).
#include <cmath>
#include <cstdio>

#include "compiler/frontend/sema_context.h"
#include "core/decimal_text.h"
#include "core/instant.h"

namespace arbc::frontend {

using namespace ast;

void Sema::check_duration(Duration& d, const std::string& what) {
  Expr& e = *d.expr;
  if (e.kind == Expr::Kind::Number) {
    char n_text[32];
    std::snprintf(n_text, sizeof n_text, "%g", e.number);
    std::string n = n_text;
    error(e.loc, what + " needs a unit: write e.g. " + n + "s, " + n + "ms or " + n + "min",
          diag::Duration);
    return;
  }
  Scope empty;
  check_expr(e, empty);
  if (!e.type) return;
  if (e.kind == Expr::Kind::Name && !e.is_duration) {
    error(e.loc,
          "constant '" + e.text + "' is " + describe(e.type) + ", but " + what +
              " must be a duration such as 500ms or 1s",
          diag::Duration);
    return;
  }
  double seconds =
      e.kind == Expr::Kind::Duration ? e.number : (e.constant ? e.constant->number : 0);
  if (!(seconds > 0) || !std::isfinite(seconds)) {
    error(e.loc, what + " must be a positive duration, such as 500ms or 1s", diag::Duration);
    return;
  }
  if (std::optional<Nanos> n = duration_nanos(e, what)) d.nanos = *n;
}

// The runtime counts time in whole nanoseconds and the proof reads each duration as that
// integer (core/instant.h), so a duration must be one. A literal is read from its text, exactly
// (`1.0000000001s` is refused, whatever double is nearest); a constant computed from others
// (`1s / 3`) from the shortest decimal of its value.
std::optional<Nanos> Sema::duration_nanos(const Expr& e, const std::string& what) {
  const Expr* literal = e.kind == Expr::Kind::Duration ? &e : nullptr;
  if (!literal && e.constant && e.constant->value->kind == Expr::Kind::Duration)
    literal = e.constant->value.get();
  double seconds = literal ? literal->number : e.constant ? e.constant->number : 0;
  std::optional<Nanos> n;
  if (literal) {
    size_t unit = literal->text.find_first_not_of("0123456789.");
    std::string_view suffix = std::string_view(literal->text).substr(unit);
    int64_t per_unit = suffix == "ms"    ? 1'000'000
                       : suffix == "min" ? 60'000'000'000
                                         : 1'000'000'000;
    n = nanos_of_decimal(std::string_view(literal->text).substr(0, unit), per_unit);
  } else {
    n = whole_nanos(seconds);
  }
  if (n) return n;
  if (seconds > seconds_of(kLongestDuration)) {
    error(e.loc, what + " must be at most 36525 days (100 years)", diag::Duration);
  } else {
    std::string value = literal ? literal->text : shortest_decimal(seconds) + "s";
    error(e.loc,
          what +
              " must be a whole number of nanoseconds (at most 9 digits after the point in "
              "seconds, 6 in ms), not " +
              value +
              ": the runtime counts time in nanoseconds, and the proof reads the duration as "
              "that count",
          diag::Duration);
  }
  return std::nullopt;
}

}  // namespace arbc::frontend
