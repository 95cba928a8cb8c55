#!/usr/bin/env bash
# navfuse bench end to end on a simulated log of one protocol ($2: vn, mip, fe, unicore):
#  - the report lists navfuse_vs_device, navfuse_vs_truth and device_vs_truth with the contract keys;
#  - navfuse_vs_truth equals `navfuse replay --truth` on the same log;
#  - --fail-above exits 3 when a bound is exceeded;
#  - bad input (shifted truth: empty overlap; a non-log input) fails with a message, non-zero;
#  - report.html renders in headless Chromium: every plot image decodes, no script errors, and
#    the screenshot is not blank.
set -euo pipefail
navfuse=$1
format=$2
python=/usr/bin/python3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$navfuse" sim --scenario drive_short --format "$format" --out log.bin --truth truth.csv --quiet
"$navfuse" bench "$format:log.bin" --truth truth.csv --report rep --quiet
"$navfuse" replay "$format:log.bin" --truth truth.csv --summary-json replay.json --quiet

"$python" - <<'PY'
import json, math
m = json.load(open("rep/metrics.json"))
r = json.load(open("replay.json"))["accuracy"]
for pair in ("navfuse_vs_device", "navfuse_vs_truth", "device_vs_truth"):
    assert pair in m, f"{pair} missing"
    assert m[pair]["samples"] > 0 and m[pair]["overlap_s"] > 0, pair
    for key in ("horizontal_m", "vertical_m", "velocity_mps", "roll_deg", "pitch_deg", "heading_deg"):
        for stat in ("rms", "p50", "p95", "p99", "max"):
            assert math.isfinite(m[pair][key][stat]), (pair, key, stat)
ours = m["navfuse_vs_truth"]
assert ours["samples"] == r["samples"], (ours["samples"], r["samples"])
for key in ("horizontal_m", "vertical_m", "velocity_mps", "roll_deg", "pitch_deg", "heading_deg"):
    for stat in ("rms", "p50", "p95", "p99", "max"):
        assert abs(ours[key][stat] - r[key][stat]) <= 1e-9 * max(1.0, abs(r[key][stat])), (key, stat)
print("metrics ok:", {p: round(m[p]["horizontal_m"]["rms"], 3) for p in m if "_vs_" in p})
PY
for f in report.html navfuse.csv device.csv truth.csv phases.csv navfuse_vs_device.csv; do test -s "rep/$f"; done

# A regression gate that must trip (exit 3) and one that must hold (exit 0).
set +e
"$navfuse" bench "$format:log.bin" --truth truth.csv --report gate --quiet --no-html \
  --fail-above navfuse_vs_truth.horizontal_m.rms=0.0001 2>gate.err
rc=$?
set -e
[ "$rc" -eq 3 ] || { echo "expected exit 3 from --fail-above, got $rc"; exit 1; }
grep -q "navfuse_vs_truth.horizontal_m.rms" gate.err
"$navfuse" bench "$format:log.bin" --truth truth.csv --report gate --quiet --no-html \
  --fail-above navfuse_vs_truth.horizontal_m.rms=1000

# Bad input: truth a day later than the log (empty overlap); a file that is no device log.
awk -F, 'NR == 1 { print; next } { $1 = sprintf("%.9f", $1 + 86400); print }' OFS=, truth.csv > late.csv
if "$navfuse" bench "$format:log.bin" --truth late.csv --report bad --quiet --no-html 2>bad.err; then
  echo "bench accepted a truth file that does not overlap the log"; exit 1
fi
grep -q "empty overlap" bad.err
if "$navfuse" bench truth.csv --report bad --quiet --no-html 2>bad2.err; then
  echo "bench accepted a CSV as a device log"; exit 1
fi
test -s bad2.err

# The report in a real browser (offline, fresh profile).
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --user-data-dir="$work/profile" --virtual-time-budget=10000)
chromium "${flags[@]}" --dump-dom "file://$work/rep/report.html" 2>/dev/null > dom.html
grep -o '<div id="render-check"[^>]*>' dom.html > mark.txt || { echo "report did not finish loading"; exit 1; }
"$python" - <<'PY'
import re
mark = open("mark.txt").read()
images = int(re.search(r'data-images="(\d+)"', mark).group(1))
decoded = int(re.search(r'data-decoded="(\d+)"', mark).group(1))
errors = int(re.search(r'data-errors="(\d+)"', mark).group(1))
assert images >= 6 and decoded == images, (images, decoded)
assert errors == 0, errors
print(f"browser: {decoded} of {images} plots decoded, no script errors")
PY
chromium "${flags[@]}" --window-size=1280,4000 --screenshot="$work/shot.png" "file://$work/rep/report.html" 2>/dev/null
"$python" - <<'PY'
import matplotlib.image as mpimg
img = mpimg.imread("shot.png")
assert img.shape[0] > 1000 and img.std() > 0.05, (img.shape, img.std())
print("screenshot not blank: std", round(float(img.std()), 3))
PY
