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
# `arbc run --transport dds` loads the DDS transport from <prefix>/lib/arbc (cli/dds_plugin.cc);
# the commands that do not need DDS do not load Fast-DDS at all. (Under ASan, Fast-DDS 2.9's own
# new/delete size mismatch is let through, as scripts/sanitize.sh does for the DDS tests.)
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}new_delete_type_mismatch=0" \
  "$arbc" run "$src/tests/install/plugin/hello.spec" --plugin "$work/plugin/libhello_modules.so" \
  --transport dds --domain 201 --duration 1s > "$work/dds-run.txt" 2>&1 ||
  { cat "$work/dds-run.txt"; fail "the installed arbc did not run over DDS"; }
grep -q "Printer got 2$" "$work/dds-run.txt" || fail "over DDS, the printer never got 2"
if ldd "$arbc" | grep -q fastrtps; then fail "arbc links Fast-DDS instead of loading it for dds"; fi
# Without the plugin, --transport dds is refused (exit 2), saying where arbc looked.
mkdir -p "$work/lonely/bin"
cp "$arbc" "$work/lonely/bin/arbc"
status=0
"$work/lonely/bin/arbc" run "$src/tests/install/plugin/hello.spec" --transport dds \
  --duration 1s > "$work/lonely.txt" 2>&1 || status=$?
[ "$status" = 2 ] || { cat "$work/lonely.txt"; fail "without arbc_dds.so, exit $status, not 2"; }
grep -q "arbc_dds.so is not installed (looked in $work/lonely/bin/arbc_dds.so" "$work/lonely.txt" ||
  { cat "$work/lonely.txt"; fail "without arbc_dds.so, no error naming where arbc looked"; }
echo "check_install.sh: the installed arbc loads the DDS transport only for --transport dds"
# arbc::arbc_dds is a target of its own: a program that reads a deployment file with it.
# (arbc always builds arbc_dds: dds/CMakeLists.txt requires Fast-DDS.)
[ -e "$work/prefix/lib/cmake/arbc/arbcDdsTargets.cmake" ] || fail "no arbcDdsTargets.cmake installed"
cmake -S "$src/tests/install/dds_consumer" -B "$work/dds" -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/dds-configure.log"
cmake --build "$work/dds" > "$work/dds.log"
got=$("$work/dds/dds_consumer" "$src/tests/dds/interop/teleop.deploy.json")
[ "$got" = "domain -1, ros2 yes, 3 topic(s), depth 100" ] || fail "dds_consumer printed: $got"
# The runtime alone does not pull DDS in: the plugin links no Fast-DDS library.
if ldd "$work/plugin/libhello_modules.so" | grep -q fastrtps; then
  fail "a plugin that links only arbc::arbc_runtime pulls Fast-DDS in"
fi
echo "check_install.sh: a program built against arbc::arbc_dds read a deployment file"
