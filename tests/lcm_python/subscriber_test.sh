#!/usr/bin/env bash
# examples/python/pose_subscriber.py receives poses from a running `navfuse run` (the demo VN-300
# drive fed at 5x real time, LCM on loopback only). Skipped (exit 77) where LCM's Python module
# is not installed (Debian 12 has no python3-lcm).
# Usage: subscriber_test.sh NAVFUSE SOURCE_DIR PYTHONPATH
set -euo pipefail
NAVFUSE=${1:?navfuse}
SRC=${2:?source dir}
export PYTHONPATH=${3:?generated python path}
if ! python3 -c "import lcm" 2> /dev/null; then
  echo "LCM's Python module (python3-lcm) is not installed: skipped"
  exit 77
fi
TMP=$(mktemp -d "${TMPDIR:-/tmp}/navfuse_pysub_XXXXXX")
nav_pid=""
cleanup() {
  [ -n "$nav_pid" ] && kill "$nav_pid" 2> /dev/null || true
  rm -rf "$TMP"
}
trap cleanup EXIT
# A multicast port of this test alone (loopback only, ttl=0).
URL="udpm://239.255.76.67:$((20000 + $$ % 40000))?ttl=0"

python3 "$SRC/examples/python/pose_subscriber.py" --url "$URL" --count 20 --timeout 20 > "$TMP/poses.txt" &
sub_pid=$!
sleep 1  # subscribed before the first pose
"$NAVFUSE" run --config "$SRC/data/demo/vn300.yaml" --in "$SRC/data/demo/vn300.vnb" --realtime 5 \
  --lcm "$URL" --quiet > "$TMP/nav.log" 2>&1 &
nav_pid=$!
if ! wait "$sub_pid"; then
  echo "FAIL: the subscriber got no poses"; cat "$TMP/poses.txt" "$TMP/nav.log"; exit 1
fi
lines=$(wc -l < "$TMP/poses.txt")
[ "$lines" -eq 20 ] || { echo "FAIL: $lines poses printed, expected 20"; exit 1; }
# Each line is a decoded pose in the demo drive's week (GPS seconds near 1.39e9) and area.
awk '{ if ($1 < 1.3e9 || $1 > 1.5e9) bad = 1 } END { exit bad }' "$TMP/poses.txt" \
  || { echo "FAIL: pose times out of the drive"; cat "$TMP/poses.txt"; exit 1; }
echo "PASS: 20 poses received from navfuse run"; head -3 "$TMP/poses.txt"
