#!/usr/bin/env bash
# Builds and installs YCM, then YARP, into a prefix: only what arbc's YARP tests and users of
# `arbc verify APP.xml` need (YARP_os, the portmonitor carrier with Lua, `yarp`, `yarpserver`,
# the Lua bindings). Installs the Debian packages it needs; safe to run twice: when the same
# archives are already installed with the same options it returns at once. Uses ccache.
#
# Usage: scripts/install-yarp.sh [PREFIX] [YARP.tar.xz YCM.tar.xz]
#   PREFIX       default $ARBC_YARP_PREFIX, else /opt/arbc-yarp
#   archives     default ../shared/vendor/yarp-3.12.3.tar.xz and ycm-0.16.2.tar.xz (beside the repo;
#                $ARBC_VENDOR_DIR overrides the folder)
# Then configure arbc with -DCMAKE_PREFIX_PATH=PREFIX (docs/yarp.md#building-yarp).
# Environment: ARBC_YARP_BUILD_DIR (default /var/tmp/arbc-yarp-build), ARBC_YARP_JOBS (nproc).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
prefix=${1:-${ARBC_YARP_PREFIX:-/opt/arbc-yarp}}
# The archives sit beside the checkout (../shared/vendor); a git worktree is one level deeper.
vendor=${ARBC_VENDOR_DIR:-$root/../shared/vendor}
[[ -d "$vendor" ]] || vendor=$root/../../shared/vendor
yarp_tar=${2:-$vendor/yarp-3.12.3.tar.xz}
ycm_tar=${3:-$vendor/ycm-0.16.2.tar.xz}
work=${ARBC_YARP_BUILD_DIR:-/var/tmp/arbc-yarp-build}
jobs=${ARBC_YARP_JOBS:-$(nproc)}

die() { echo "install-yarp: $*" >&2; exit 2; }
[[ $# -le 1 || $# -eq 3 ]] || die "usage: install-yarp.sh [PREFIX] [YARP.tar.xz YCM.tar.xz]"
for f in "$yarp_tar" "$ycm_tar"; do
  [[ -r "$f" ]] || die "cannot read $f (give the YARP and YCM source archives as arguments)"
done
[[ "$prefix" = /* ]] || prefix=$(pwd)/$prefix

# What YARP is built with; a change here (or in either archive) rebuilds.
yarp_options=(
  -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON
  -DSKIP_ACE=ON -DYARP_USE_SYSTEM_SQLite3=ON
  -DYARP_COMPILE_libYARP_math=OFF -DYARP_COMPILE_GUIS=OFF -DYARP_COMPILE_TESTS=OFF
  -DYARP_COMPILE_EXECUTABLES=ON -DYARP_COMPILE_UNMAINTAINED=OFF
  -DYARP_COMPILE_yarprobotinterface=OFF -DYARP_COMPILE_yarpmanager-console=OFF
  -DYARP_COMPILE_yarpdatadumper=OFF -DYARP_COMPILE_yarpActionsPlayer=OFF
  -DYARP_COMPILE_yarpAudioPlayer=OFF -DYARP_COMPILE_yarpconnectionsinfo=OFF
  -DYARP_COMPILE_yarpRobotDescriptionInfo=OFF -DYARP_COMPILE_libYARP_robotinterface=OFF
  # Device plugins off needs SKIP_AudioRecorderWrapper too (a misspelled variable in 3.12.3).
  -DYARP_COMPILE_DEVICE_PLUGINS=OFF -DSKIP_AudioRecorderWrapper=ON
  -DYARP_COMPILE_PORTMONITOR_PLUGINS=OFF
  -DYARP_COMPILE_CARRIER_PLUGINS=ON -DENABLE_yarpcar_portmonitor=ON
  -DENABLE_yarpcar_shmem=OFF -DENABLE_yarpcar_human=OFF -DENABLE_yarpcar_mjpeg=OFF
  -DENABLE_yarpcar_bayer=OFF -DENABLE_yarpcar_priority=OFF -DENABLE_yarpcar_unix_stream=OFF
  -DENABLE_yarpcar_websocket=OFF -DENABLE_yarpcar_gstreamer=OFF -DENABLE_yarpcar_mpi=OFF
  -DENABLE_yarpcar_mpibcast=OFF
  # The Lua in the portmonitor carrier has no switch: it is compiled in when Lua is found.
  -DLUA_INCLUDE_DIR=/usr/include/lua5.4
  -DLUA_LIBRARY=/usr/lib/x86_64-linux-gnu/liblua5.4.so
  -DYARP_COMPILE_BINDINGS=ON -DCREATE_LUA=ON
)
# Optional packages found on one machine and not on another would change the result.
for p in ACE RobotTestingFramework Libedit Eigen3 Qt5 QCustomPlot Graphviz QGVCore OpenCV \
         Libdc1394 JPEG ZLIB PNG MPI OpenGL FTDI FFMPEG SDL PortAudio ZFP OpenNI2 PCL Doxygen \
         GObject GLIB2 SOXR GStreamer GStreamerPluginsBase BISON FLEX I2C Libv4l2 Libv4lconvert \
         Python3 Java Ruby Octave Perl PHP TCL CSharp; do
  yarp_options+=("-DCMAKE_DISABLE_FIND_PACKAGE_$p=ON")
done

stamp="$prefix/share/arbc-yarp/installed"
want=$( { sha256sum "$yarp_tar" "$ycm_tar" | cut -d' ' -f1; printf '%s\n' "${yarp_options[@]}"; } \
        | sha256sum | cut -d' ' -f1)
installed_ok() {
  [[ -f "$stamp" && "$(cat "$stamp")" == "$want" ]] &&
  [[ -x "$prefix/bin/yarp" && -x "$prefix/bin/yarpserver" ]] &&
  [[ -f "$prefix/lib/yarp/yarp_portmonitor.so" && -f "$prefix/lib/lua/5.4/yarp.so" ]] &&
  [[ -f "$prefix/lib/cmake/YARP/YARPConfig.cmake" ]]
}
if installed_ok; then
  echo "install-yarp: YARP already installed in $prefix"
  exit 0
fi

# Debian packages (only the missing ones).
packages=(build-essential cmake xz-utils ccache swig liblua5.4-dev lua5.4 libsqlite3-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo_=()
[[ $(id -u) -ne 0 ]] && sudo_=(sudo)
if ((${#missing[@]} > 0)); then
  echo "install-yarp: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_[@]}" apt-get update -qq
  "${sudo_[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# Writing into the prefix may need root; building never does.
install_=()
mkdir -p "$prefix" 2>/dev/null && [[ -w "$prefix" ]] || install_=("${sudo_[@]}")

# A fixed build directory lets ccache reuse objects between runs (and between CI jobs).
export CCACHE_BASEDIR=$work CCACHE_NOHASHDIR=1
launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
rm -rf "$work" && mkdir -p "$work/src"
echo "install-yarp: building YCM and YARP in $work (-j$jobs), installing into $prefix"
tar -xJf "$ycm_tar" -C "$work/src"
tar -xJf "$yarp_tar" -C "$work/src"
ycm_src=$(find "$work/src" -maxdepth 1 -type d -name 'ycm*' | head -1)
yarp_src=$(find "$work/src" -maxdepth 1 -type d -name 'yarp*' | head -1)
[[ -n "$ycm_src" && -n "$yarp_src" ]] || die "archives do not unpack to ycm-*/ and yarp-*/"
log=$work/build.log
run() { "$@" >>"$log" 2>&1 || { tail -40 "$log" >&2; die "failed: $* (log: $log)"; }; }

run cmake -S "$ycm_src" -B "$work/ycm" -DCMAKE_INSTALL_PREFIX="$prefix" -DYCM_USE_CMAKE_PROPOSED=OFF
run cmake --build "$work/ycm" -j"$jobs"
run "${install_[@]}" cmake --install "$work/ycm"

run cmake -S "$yarp_src" -B "$work/yarp" -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DYCM_DIR="$prefix/share/cmake/YCM" -DCMAKE_PREFIX_PATH="$prefix" "${launcher[@]}" \
  "${yarp_options[@]}"
# SWIG does not wait for headers generated during the build: build those libraries first.
run cmake --build "$work/yarp" -j"$jobs" --target YARP_dev YARP_init
run cmake --build "$work/yarp" -j"$jobs"
run "${install_[@]}" cmake --install "$work/yarp"

echo "$want" >"$work/stamp"
run "${install_[@]}" mkdir -p "$prefix/share/arbc-yarp"
run "${install_[@]}" cp "$work/stamp" "$stamp"
installed_ok || die "installed, but $prefix lacks yarp, yarpserver, the portmonitor carrier or yarp.so"
rm -rf "$work"
echo "install-yarp: YARP installed in $prefix (configure arbc with -DCMAKE_PREFIX_PATH=$prefix)"
