// Which builtin an unknown function name most likely means. Edit distance catches typos
// (`lne`, `nrom`), but not the names other languages give the same functions: `length(xs)`,
// `size(xs)` or `count(xs)` for `len(xs)` are no typo of `len`, nor `distance` of `dist`.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/type.h"

namespace arbc::frontend {

// The builtin to suggest for the unknown function `name` (docs/language.md#builtins): the
// closest of `builtins` by edit distance; else, for a name (or a typo of a name) from the
// list of other languages' spellings, the builtin it means. `length` means `norm` when its
// first argument is a vec3 (a vector's length), `len` otherwise; `first_arg` may be null.
std::optional<std::string> meant_builtin(std::string_view name,
                                         const std::vector<std::string>& builtins,
                                         const TypePtr& first_arg);

}  // namespace arbc::frontend
