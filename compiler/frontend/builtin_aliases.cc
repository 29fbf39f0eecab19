#include "compiler/frontend/builtin_aliases.h"

#include "core/builtins.h"
#include "core/suggest.h"

namespace arbc::frontend {

namespace {

struct Alias {
  const char* name;  // as another language spells it
  Builtin builtin;   // what it means here (core/builtins.h)
};

// Only names that are not builtins of their own here (the language has no `count` of items
// that satisfy a predicate, so `count(xs)` can only mean how many there are). JavaScript's
// `xs.length`, C++'s and Java's `size()`, C#'s and SQL's `count`; `distance` and `magnitude`
// from vector libraries.
constexpr Alias kAliases[] = {
    {"length", Builtin::Len},     {"size", Builtin::Len},      {"count", Builtin::Len},
    {"magnitude", Builtin::Norm}, {"distance", Builtin::Dist},
};

}  // namespace

std::optional<std::string> meant_builtin(std::string_view name,
                                         const std::vector<std::string>& builtins,
                                         const TypePtr& first_arg) {
  if (auto best = closest_name(name, builtins)) return best;
  std::vector<std::string> spellings;
  for (const Alias& a : kAliases) spellings.emplace_back(a.name);
  std::string spelling(name);
  bool exact = false;
  for (const std::string& s : spellings) exact |= s == spelling;
  if (!exact) {
    auto typo = closest_name(name, spellings);  // `lenght` is a typo of `length`
    if (!typo) return std::nullopt;
    spelling = *typo;
  }
  if (spelling == "length" && first_arg && first_arg->kind == Type::Kind::Vec3)
    return std::string(builtin_info(Builtin::Norm)->name);
  for (const Alias& a : kAliases)
    if (spelling == a.name) return std::string(builtin_info(a.builtin)->name);
  return std::nullopt;
}

}  // namespace arbc::frontend
