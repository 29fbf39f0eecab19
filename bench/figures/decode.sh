#!/usr/bin/env bash
# What a big ROS 2 message costs a mediator (issue 41): instructions per message of
# bench/dds/decode_bench.cc, a LaserScan of 1,080 ranges decoded from its CDR bytes, read into a
# spec value, judged by a rule that reads one field and delivered, against the same path for a
# message of three float32s (the baseline), each counted by callgrind over a window of its
# messages (bench/callgrind_window.sh: 100 LaserScans after 20, 10,000 three-field messages after
# 2,000). Needs valgrind (installed by bench/run).
set -euo pipefail
source "$(dirname "$0")/../callgrind_window.sh"
callgrind_bench decode.sh bench/dds/decode_bench
scan=$(callgrind_window "$bench" BM_DecodeLaserScan "$work" 100)
three=$(callgrind_window "$bench" BM_DecodeThreeFields "$work")
python3 - "$scan" "$three" <<'PY'
import json, sys
scan, three = map(float, sys.argv[1:])
print(json.dumps(dict(name="decode_laser_scan_instructions", value=round(scan), unit="instructions",
                      baseline=round(three), ratio=round(scan / three, 1))))
PY
