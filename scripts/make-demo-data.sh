#!/usr/bin/env bash
# Regenerates the demo logs in data/demo/ with navfuse's own simulator (deterministic: the same
# build writes the same bytes). Usage: scripts/make-demo-data.sh [BUILD_DIR]   (default build/release)
#
#   drive_short: ~3-minute drive, 30 s static start, a 30 s GNSS outage at 20 m/s (95-125 s),
#   industrial IMU at 200 Hz, 5 Hz GNSS, 50 Hz vehicle speed at the rear axle.
#   vn300.vnb + vn300_wheel.p1log  VN-300 binary (IMU, GNSS, INS at 50 Hz) + FusionEngine wheel log
#   cv7.mip                        CV7 MIP (IMU, GNSS, odometer, 0x82 filter at 20 Hz)
#   atlas.p1log                    FusionEngine (raw IMU, GNSS fixes, vehicle speed, Pose at 10 Hz)
#   um220.log                      UM220-INS ASCII (GYOACC IMU, GNSS, NAVPOS/NAVATT at 5 Hz)
#   truth.csv                      the simulated truth at 200 Hz
# Every file stays under 5 MB.
set -euo pipefail
BUILD_DIR=${1:-build/release}
NAVFUSE="$BUILD_DIR/apps/navfuse"
OUT=data/demo
[ -x "$NAVFUSE" ] || { echo "make-demo-data: $NAVFUSE not found (build first)" >&2; exit 1; }
mkdir -p "$OUT"
SIM=("$NAVFUSE" sim --scenario drive_short --quiet)
"${SIM[@]}" --format vn --out "$OUT/vn300.vnb" --wheel-out "$OUT/vn300_wheel.p1log" --truth "$OUT/truth.csv" \
  --device-rate 50
"${SIM[@]}" --format mip --out "$OUT/cv7.mip" --device-rate 20
"${SIM[@]}" --format fe --out "$OUT/atlas.p1log"
"${SIM[@]}" --format unicore --out "$OUT/um220.log"
for f in "$OUT"/*.vnb "$OUT"/*.p1log "$OUT"/*.mip "$OUT"/*.log "$OUT"/truth.csv; do
  size=$(stat -c %s "$f")
  if [ "$size" -ge 5000000 ]; then echo "make-demo-data: $f is $size bytes (limit 5 MB)" >&2; exit 1; fi
  echo "$f: $size bytes"
done
