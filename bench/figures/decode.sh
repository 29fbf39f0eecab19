#!/usr/bin/env bash
# What a big ROS 2 message costs a mediator (issue 41): instructions per message of
# bench/dds/decode_bench.cc, a LaserScan of 1,080 ranges decoded from its CDR bytes, read into a
# spec value, judged by a rule that reads one field and delivered, against the same path for a
# message of three float32s (the baseline), each counted by callgrind over a window of its
# messages (bench/callgrind_window.sh: 100 LaserScans after 20, 10,000 three-field messages after
# 2,000); and the LaserScan's encoding by the mediator's writer against Fast-DDS's (100 after 20).
# Needs valgrind (installed by bench/run).
set -euo pipefail
source "$(dirname "$0")/../callgrind_window.sh"
callgrind_bench decode.sh bench/dds/decode_bench
scan=$(callgrind_window "$bench" BM_DecodeLaserScan "$work" 100)
three=$(callgrind_window "$bench" BM_DecodeThreeFields "$work")
# The write side: the same LaserScan to its bytes, by the mediator's writer against Fast-DDS's
# dynamic data (the baseline: the path before dds/cdr_write.h).
ours=$(callgrind_window "$bench" BM_EncodeLaserScan "$work" 100)
theirs=$(callgrind_window "$bench" BM_EncodeLaserScanFastDds "$work" 100)
python3 - "$scan" "$three" "$ours" "$theirs" <<'PY'
import json, sys
scan, three, ours, theirs = map(float, sys.argv[1:])
print(json.dumps(dict(name="decode_laser_scan_instructions", value=round(scan), unit="instructions",
                      baseline=round(three), ratio=round(scan / three, 1))))
print(json.dumps(dict(name="encode_laser_scan_instructions", value=round(ours),
                      unit="instructions", baseline=round(theirs), ratio=round(ours / theirs, 4))))
PY
