# Sourced by figure scripts: `callgrind_window BINARY BENCHMARK WORK_DIR [COUNT]` prints the
# instructions per message of BENCHMARK's window (bench/instruction_window.h: COUNT messages,
# 10,000 by default, after a warm-up), counted by callgrind. A count does not move with what else
# the shared machine runs, so two builds compare exactly where their times only compare by
# interleaved medians.
callgrind_window() {
  local bench=$1 name=$2 out=$3/$2 count=${4:-10000}
  # Long enough a run that one of the benchmark's runs reaches the end of the window.
  valgrind --tool=callgrind --collect-atstart=yes --callgrind-out-file="$out" \
    "$bench" --benchmark_filter="^$name(/.*)?\$" --benchmark_min_time=3 >/dev/null 2>&1
  python3 - "$out.1" "$count" <<'PY'
import sys
try:
    lines = open(sys.argv[1]).read().splitlines()
except OSError:
    sys.exit("callgrind_window: no window was dumped (the benchmark ran too few messages)")
totals = [l for l in lines if l.startswith("totals:") or l.startswith("summary:")]
print(int(totals[0].split()[1]) / int(sys.argv[2]))
PY
}

# `callgrind_bench SCRIPT RELATIVE_PATH` sets $bench to the benchmark binary of the bench tree
# ($ARBC_BENCH_BUILD, else build-bench/) and $work to a scratch folder removed at exit; exits 2
# saying what is missing (the binary, or valgrind).
callgrind_bench() {
  local script=$1 root
  root=${ARBC_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
  local build=${ARBC_BENCH_BUILD:-$root/build-bench}
  bench=$build/$2
  if [ ! -x "$bench" ]; then
    echo "$script: $bench is missing; build the Release tree first (bench/run does)" >&2
    exit 2
  fi
  if ! command -v valgrind >/dev/null; then
    echo "$script: valgrind is missing (apt-get install valgrind)" >&2
    exit 2
  fi
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
}
