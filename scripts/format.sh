#!/usr/bin/env bash
# clang-format (the repository's .clang-format) over the project's own C++:
#   scripts/format.sh           rewrites every file that differs
#   scripts/format.sh --check   lists them and fails; ctest runs this as `code_format`
# The files are the .cc and .h files under the source folders (no build trees, no generated
# parser: that lives in the build directory).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mapfile -t files < <(find bench cli compiler core dds examples fuzz harness import lsp report runtime tests verify \
  -type f \( -name '*.cc' -o -name '*.h' \) | sort)
if [ "${1:-}" = --check ]; then
  # One clang-format process for all files (one per file took a minute); it names each file
  # that differs in its "FILE:LINE:COL: error: code should be clang-formatted" lines.
  if ! report=$(clang-format --dry-run --Werror "${files[@]}" 2>&1); then
    printf 'format.sh: not in clang-format style (run scripts/format.sh):\n' >&2
    printf '%s\n' "$report" | sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: error: .*/  \1/p' | sort -u >&2
    exit 1
  fi
  echo "format.sh: ${#files[@]} files in clang-format style"
  exit 0
fi
clang-format -i "${files[@]}"
