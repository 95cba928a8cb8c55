#!/usr/bin/env bash
# `make demo`: replays the bundled VN-300 sample (data/demo, made by navfuse's simulator, see
# scripts/make-demo-data.sh) together with its FusionEngine wheel-speed log through the filter,
# prints the summary and the error against the simulated truth, and writes the outputs to
# build/demo-out/. Usage: scripts/demo.sh BUILD_DIR
set -euo pipefail
BUILD_DIR=${1:?usage: scripts/demo.sh BUILD_DIR}
NAVFUSE="$BUILD_DIR/apps/navfuse"
DATA=data/demo
OUT=build/demo-out
[ -x "$NAVFUSE" ] || { echo "demo: $NAVFUSE not found (build first)" >&2; exit 1; }
mkdir -p "$OUT"

echo "== navfuse replay: VN-300 log + FusionEngine wheel-speed log, merged by measurement time"
"$NAVFUSE" replay --config "$DATA/vn300.yaml" "vn:$DATA/vn300.vnb" "fe:$DATA/vn300_wheel.p1log" \
  --truth "$DATA/truth.csv" \
  --fe-out "$OUT/navfuse.p1log" --mip-out "$OUT/navfuse.mip" --csv "$OUT/navfuse.csv" \
  --summary-json "$OUT/summary.json"

echo
echo "== outputs in $OUT/"
echo "   navfuse.p1log  FusionEngine Pose/PoseAux/GNSSInfo/IMUOutput (decode: $NAVFUSE decode $OUT/navfuse.p1log)"
echo "   navfuse.mip    MIP 0x82 filter packets"
echo "   navfuse.csv    one row per pose (time, LLH, NED velocity, roll/pitch/yaw, 1-sigma, mode)"
echo "   summary.json   the summary above, with the accuracy against truth under \"accuracy\""
