#!/usr/bin/env bash
# `navfuse smooth` throughput and memory (issue 16's scale goal: a 1-hour 200 Hz log within 2 GB
# and at most 10x the forward replay's time): that hour of 200 Hz drive (`navfuse sim --scenario
# drive_1h`: three laps of drive_outage, a 120 s GNSS outage in each, VN-300 binary with a 50 Hz
# wheel-speed log) replayed and smoothed as whole processes, timed and measured by /usr/bin/time
# (wall time, peak RSS). Prints IMU samples/s of each, the smooth/replay time ratio, peak RSS, the
# forward record's size on disk (from the summary) per hour of log, and the peak RSS growth per
# hour of log: the slope between this log and the 3-minute drive_short (the fixed part, code and
# buffers, cancels out).
#
# Usage: tests/bench/smooth_throughput.sh [BUILD_DIR] [RUNS]     (default build/release, 3)
BENCH_NAME=smooth_throughput
DEFAULT_RUNS=3
source "$(dirname "$0")/whole_process_setup.sh"

"$NAVFUSE" sim --scenario drive_1h --format vn --out "$work/drive.vnb" --wheel-out "$work/wheel.p1log" \
  --device-rate 50 --quiet
"$NAVFUSE" smooth "$work/drive.vnb" "$work/wheel.p1log" --rate 0 --csv "$work/warm.csv" \
  --summary-json "$work/summary.json" --quiet
"$NAVFUSE" sim --scenario drive_short --format vn --out "$work/short.vnb" --wheel-out "$work/short_wheel.p1log" \
  --device-rate 50 --quiet
"$NAVFUSE" smooth "$work/short.vnb" "$work/short_wheel.p1log" --rate 0 --csv "$work/warm.csv" \
  --summary-json "$work/short_summary.json" --quiet

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
measure() {  # command words...; prints "wall_s rss_kb" of the median-time run
  local times=() rss=()
  for i in $(seq "$RUNS"); do
    /usr/bin/time -f "%e %M" -o "$work/time.txt" "$@" --quiet
    read -r wall_s rss_kb < "$work/time.txt"
    times+=("$wall_s"); rss+=("$rss_kb")
  done
  echo "$(median "${times[@]}") $(printf '%s\n' "${rss[@]}" | sort -g | tail -1)"
}
read -r replay_s replay_kb < <(measure "$NAVFUSE" replay "$work/drive.vnb" "$work/wheel.p1log" --rate 0 --csv "$work/fwd.csv")
read -r smooth_s smooth_kb < <(measure "$NAVFUSE" smooth "$work/drive.vnb" "$work/wheel.p1log" --rate 0 --csv "$work/smooth.csv")
read -r short_s short_kb < <(measure "$NAVFUSE" smooth "$work/short.vnb" "$work/short_wheel.p1log" --rate 0 --csv "$work/smooth.csv")
python3 - "$work/summary.json" "$replay_s" "$replay_kb" "$smooth_s" "$smooth_kb" "$work/short_summary.json" "$short_kb" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
replay_s, replay_kb, smooth_s, smooth_kb = float(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5])
short_n = json.load(open(sys.argv[6]))["measurements"]["imu"]["used"]
short_kb = int(sys.argv[7])
n = s["measurements"]["imu"]["used"]
record_mb = s["smoother"]["record_mb"]
hours = n / 200.0 / 3600.0
print(f"log: {n} IMU samples ({hours * 60:.1f} min at 200 Hz)")
print(f"replay (CSV per sample): {replay_s:.2f} s -> {n / replay_s:,.0f} IMU samples/s, peak RSS {replay_kb / 1024:.0f} MB")
print(f"smooth (CSV per sample): {smooth_s:.2f} s -> {n / smooth_s:,.0f} IMU samples/s, peak RSS {smooth_kb / 1024:.0f} MB; "
      f"{smooth_s / replay_s:.1f}x the replay")
print(f"forward record on disk: {record_mb:.0f} MB -> {record_mb / hours:.0f} MB per hour of log")
short_hours = short_n / 200.0 / 3600.0
slope = (smooth_kb - short_kb) / 1024 / (hours - short_hours)
print(f"smooth peak RSS: {short_kb / 1024:.0f} MB for {short_hours * 60:.1f} min, {smooth_kb / 1024:.0f} MB for "
      f"{hours * 60:.1f} min -> {slope:.0f} MB per hour of log; a 1-hour log: ~{short_kb / 1024 + slope * (1 - short_hours):.0f} MB")
PY
