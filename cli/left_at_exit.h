// Large results a command no longer needs, left to the operating system at exit rather than
// freed one node at a time.
//
// Why: freeing the AST of a 10,000-rule spec was 4.5 % of `arbc check`'s instructions on the
// thread the user waits for, and freeing the lowered app 3 % of `arbc build`'s
// (docs/benchmarks.md); when the process is about to end, the kernel takes the whole heap back
// at once. (Compilers do the same: clang's -disable-free.) Kept objects stay reachable from a
// global, so leak checkers do not report them.
#pragma once

#include <memory>
#include <type_traits>
#include <utility>

namespace arbc::cli {

// main() calls this before a command after which the process ends. Until then, and in
// `arbc run` (which builds, then keeps running), leave_at_exit does nothing.
void process_ends_after_command();

// Takes `value` over until the process exits, if it is about to; otherwise leaves it to the
// caller, who destroys it as usual.
template <typename T>
void leave_at_exit(T& value);

namespace detail {
bool process_ends_soon();
void keep(std::shared_ptr<void> value);
}  // namespace detail

template <typename T>
void leave_at_exit(T& value) {
  if (detail::process_ends_soon()) detail::keep(std::make_shared<T>(std::move(value)));
}

}  // namespace arbc::cli
