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
