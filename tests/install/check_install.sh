#!/bin/sh
# The module author's path end to end: install arbc into a scratch prefix, build a plugin
# outside the tree with find_package(arbc), then check, build and run an app on it with the
# installed arbc.
# usage: check_install.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -eu
src=$1
build=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$src/tests/install/plugin" -B "$work/plugin" -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/configure.log"
cmake --build "$work/plugin" > "$work/plugin.log"
arbc=$work/prefix/bin/arbc
"$arbc" check "$src/tests/install/plugin/hello.spec"
"$arbc" run "$src/tests/install/plugin/hello.spec" --plugin "$work/plugin/libhello_modules.so" \
  --duration 1s > "$work/run.txt" 2>&1 || { cat "$work/run.txt"; exit 1; }
cat "$work/run.txt"
# Ten counts in a second, of which the five even ones are delivered, in order.
fail() { echo "check_install.sh: $1 (output above)" >&2; exit 1; }
grep -q "Printer got 2$" "$work/run.txt" || fail "the printer never got 2"
grep -q "Printer got 10$" "$work/run.txt" || fail "the printer never got 10"
if grep -q "Printer got [13579]$" "$work/run.txt"; then fail "an odd count was delivered"; fi
echo "check_install.sh: a plugin built against the installed package ran"
