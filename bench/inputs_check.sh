#!/usr/bin/env bash
# bench/run stops at the first figure script that fails, and nothing else runs those scripts:
# this keeps the inputs they assume true under ctest (bench_inputs). The resource spec that
# verify_data.sh times must be proved, with and without its resource (a small one: the shape is
# what matters), and the word lsp_latency.py edits must still be in specs/table_clean.spec.
# Usage: inputs_check.sh ARBC (from the repository's root)
set -u
arbc=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for extra in "" --no-resource; do
  python3 bench/verify/gen_resource_spec.py 20 4 "$work/r.spec" $extra
  if ! "$arbc" verify "$work/r.spec" >"$work/out.txt" 2>&1; then
    echo "FAIL: gen_resource_spec.py 20 4 $extra is not proved:"; head -20 "$work/out.txt"
    status=1
  fi
done
word=$(python3 -c 'import re,sys; print(re.search(r"^WORD, TYPO = \"([^\"]*)\"", open("bench/lsp_latency.py").read(), re.M).group(1))')
if ! grep -qF "$word" specs/table_clean.spec; then
  echo "FAIL: bench/lsp_latency.py edits '$word', which specs/table_clean.spec does not have"
  status=1
fi
[ $status -eq 0 ] && echo "ok: the benchmarks' inputs hold"
exit $status
