#!/usr/bin/env bash
# examples/python/pose_subscriber.py receives poses from a running `navfuse run` (the demo VN-300
# drive fed at 10x real time, LCM on loopback only), and what it decodes is what the same run
# wrote in its own CSV: time, mode, position and velocity of 20 poses in navigation.
# LCM's Python module: the system's (python3-lcm) where installed, else PyPI's `lcm` in a
# virtualenv made once in the build tree (Debian 12 has no python3-lcm). Like the
# fusion-engine-client test, a pip failure (no network) fails the test.
# Usage: subscriber_test.sh NAVFUSE SOURCE_DIR PYTHONPATH VENV_DIR
set -euo pipefail
NAVFUSE=${1:?navfuse}
SRC=${2:?source dir}
export PYTHONPATH=${3:?generated python path}
VENV=${4:?virtualenv dir}
PY=python3
if ! python3 -c "import lcm" 2> /dev/null; then
  if [ ! -x "$VENV/bin/python" ] || ! "$VENV/bin/python" -c "import lcm" 2> /dev/null; then
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install --quiet "lcm==1.5.3"
  fi
  PY="$VENV/bin/python"
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

"$PY" "$SRC/examples/python/pose_subscriber.py" --url "$URL" --mode navigation --count 20 --timeout 30 \
  > "$TMP/poses.txt" &
sub_pid=$!
sleep 1  # subscribed before the first pose
"$NAVFUSE" run --config "$SRC/data/demo/vn300.yaml" --in "$SRC/data/demo/vn300.vnb" --realtime 10 \
  --lcm "$URL" --csv "$TMP/run.csv" --quiet > "$TMP/nav.log" 2>&1 &
nav_pid=$!
if ! wait "$sub_pid"; then
  echo "FAIL: the subscriber got no poses in navigation"; cat "$TMP/poses.txt" "$TMP/nav.log"; exit 1
fi
wait "$nav_pid" || { echo "FAIL: navfuse run failed"; cat "$TMP/nav.log"; exit 1; }
nav_pid=""
lines=$(wc -l < "$TMP/poses.txt")
[ "$lines" -eq 20 ] || { echo "FAIL: $lines poses printed, expected 20"; exit 1; }
# Each printed pose against the CSV row of the same time, to the printed precision.
python3 - "$TMP/poses.txt" "$TMP/run.csv" <<'PY'
import csv, sys
rows = {round(float(r["time_s"]), 3): r for r in csv.DictReader(open(sys.argv[2]))}
bad = 0
for line in open(sys.argv[1]):
    f = line.split()
    t, mode, lat, lon, h = float(f[0]), f[1], float(f[3]), float(f[5]), float(f[7])
    vel = [float(v) for v in f[11:14]]
    r = rows.get(round(t, 3))
    if r is None:
        print(f"FAIL: no CSV row at {t:.3f}"); bad += 1; continue
    checks = [(mode, r["mode"], 0), (lat, float(r["lat_deg"]), 1.5e-7), (lon, float(r["lon_deg"]), 1.5e-7),
              (h, float(r["height_m"]), 0.006)] + [(v, float(r[k]), 0.006) for v, k in zip(vel, ["vn_mps", "ve_mps", "vd_mps"])]
    for got, want, tol in checks:
        if (got != want) if tol == 0 else abs(got - want) > tol:
            print(f"FAIL at {t:.3f}: decoded {got}, CSV {want}"); bad += 1
sys.exit(1 if bad else 0)
PY
echo "PASS: 20 poses in navigation received from navfuse run, equal to its CSV"; head -3 "$TMP/poses.txt"
