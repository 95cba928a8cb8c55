#!/usr/bin/env bash
# Whole-process replay throughput (issue 13's goal: >= 700,000 IMU samples/s): a 9-minute 200 Hz
# VN-300 log with a 50 Hz wheel-speed log, made by `navfuse sim`, replayed with a FusionEngine
# Pose + PoseAux + IMUOutput per IMU sample. Each run is timed from process start to exit by
# /usr/bin/time (set-up, decode, filter, encoding and the output file's commit included); the
# median of RUNS runs is printed with the rate it gives.
#
# Usage: tests/bench/replay_throughput.sh [BUILD_DIR] [RUNS]     (default build/release, 5)
BENCH_NAME=replay_throughput
DEFAULT_RUNS=5
source "$(dirname "$0")/whole_process_setup.sh"

"$NAVFUSE" sim --scenario drive_9min --format vn --out "$work/drive.vnb" --wheel-out "$work/wheel.p1log" \
  --device-rate 50 --quiet
"$NAVFUSE" replay "$work/drive.vnb" "$work/wheel.p1log" --rate 0 --fe-out "$work/warm.p1log" \
  --summary-json "$work/summary.json" --quiet
samples=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['measurements']['imu']['used'])" "$work/summary.json")

times=()
for i in $(seq "$RUNS"); do
  /usr/bin/time -f "%e %M" -o "$work/time.txt" \
    "$NAVFUSE" replay "$work/drive.vnb" "$work/wheel.p1log" --rate 0 --fe-out "$work/out.p1log" --quiet
  read -r wall_s rss_kb < "$work/time.txt"
  times+=("$wall_s")
  printf 'run %d: %s s, peak RSS %d MB\n' "$i" "$wall_s" $((rss_kb / 1024))
done
median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
python3 - "$samples" "$median" <<'PY'
import sys
n, t = int(sys.argv[1]), float(sys.argv[2])
print(f"IMU samples: {n}; median whole-process time {t:.3f} s -> {n / t:,.0f} IMU samples/s")
PY
