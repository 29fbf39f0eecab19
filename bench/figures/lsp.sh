#!/usr/bin/env bash
# Figures for issue 20: how long `arbc lsp` makes a keystroke wait on specs/table_clean.spec
# (bench/lsp_latency.py): an edit until its diagnostics (baseline: a whole `arbc check`
# process on the same file), and a hover sent right after an edit (baseline: the same hover
# with no edit pending). Medians of 41 edits. Target: at most 100 ms per keystroke.
# Env (set by bench/run): ARBC (Release arbc), ARBC_ROOT.
set -euo pipefail
root=${ARBC_ROOT:-$(cd "$(dirname "$0")/../.." && pwd)}
arbc=${ARBC:-$root/build/cli/arbc}
python3 "$root/bench/lsp_latency.py" "$arbc" "$root/specs/table_clean.spec" 41
