#!/usr/bin/env bash
# navfuse against the public KF-GINS (i2Nav-WHU, github.com/i2Nav-WHU/KF-GINS: an EKF GNSS/INS in
# C++, built as its README says, Release) on the same drive, each timed as a whole process: issue
# 13 sets navfuse's replay at ten times KF-GINS' rate measured side by side. This machine's speed
# varies from day to day (README, Performance); the ratio of two programs timed in turn does not.
#
# The drive is replay_throughput.sh's: `navfuse sim --scenario drive_9min` as a VN-300 log (200 Hz
# IMU increments, 5 Hz GNSS) with a 50 Hz wheel-speed log. What each program does with it:
#   navfuse   replay of the VN-300 and wheel logs, a FusionEngine Pose + PoseAux + IMUOutput per
#             IMU sample (exactly replay_throughput.sh's command);
#   KF-GINS   the same IMU increments and GNSS positions as its text inputs (navfuse decode, then
#             the columns KF-GINS reads: GPS seconds of week, dtheta and dv in the body FRD frame;
#             latitude, longitude, height and their NED stds), initial state from the simulation's
#             truth, the simulated IMU's noise figures (industrial grade, apps/sim/imu_error_model.cpp)
#             and the antenna lever arm; it writes its three text files per IMU sample.
# Text conversion and config happen before the timed runs. Each program runs RUNS times, in turn;
# the medians and their ratio are printed, with KF-GINS' last position against the truth (that it
# navigated, not how well: it fuses no wheel speed).
#
# Usage: tests/bench/kfgins_compare.sh [BUILD_DIR] [RUNS]     (default build/release, 9)
# KF_GINS_DIR=DIR uses a KF-GINS checkout (its src/ folder); without it the script clones the
# repository into its scratch folder. KF-GINS is built here from its five sources with -O3
# -DNDEBUG against Debian's Eigen, yaml-cpp and abseil (apt-get install libabsl-dev); the script
# prints "skipped" when any of that is missing (no network, no abseil).
BENCH_NAME=kfgins_compare
DEFAULT_RUNS=9
source "$(dirname "$0")/whole_process_setup.sh"

kf=${KF_GINS_DIR:-$work/KF-GINS}
if [ -z "${KF_GINS_DIR:-}" ] &&
   ! git clone --quiet --depth 1 https://github.com/i2Nav-WHU/KF-GINS "$kf" >"$work/git.log" 2>&1; then
  echo "skipped: could not clone KF-GINS (set KF_GINS_DIR to a checkout):"
  tail -2 "$work/git.log"
  exit 0
fi
sources=("$kf/src/kf_gins.cpp" "$kf/src/fileio/fileloader.cc" "$kf/src/fileio/filesaver.cc"
         "$kf/src/kf-gins/gi_engine.cpp" "$kf/src/kf-gins/insmech.cpp")
for f in "${sources[@]}"; do
  [ -f "$f" ] || { echo "skipped: $f not found (a KF-GINS checkout?)"; exit 0; }
done
if ! libs=$(pkg-config --libs absl_time absl_strings absl_str_format yaml-cpp 2>/dev/null); then
  echo "skipped: abseil or yaml-cpp not found by pkg-config (apt-get install libabsl-dev libyaml-cpp-dev)"
  exit 0
fi
# shellcheck disable=SC2086  # $libs is a list of flags
g++ -std=c++14 -O3 -DNDEBUG -w -I"$kf/src" -I/usr/include/eigen3 "${sources[@]}" $libs -o "$work/KF-GINS"

"$NAVFUSE" sim --scenario drive_9min --format vn --out "$work/drive.vnb" --wheel-out "$work/wheel.p1log" \
  --device-rate 50 --truth "$work/truth.csv" --quiet
"$NAVFUSE" decode "$work/drive.vnb" --format jsonl -o "$work/drive.jsonl" --quiet
mkdir -p "$work/kf_out"
python3 - "$work" <<'PY'
import csv, json, sys
work = sys.argv[1]
week_ns = 604800 * 10**9
with open(f"{work}/drive.jsonl") as src, open(f"{work}/imu.txt", "w") as imu, open(f"{work}/gnss.txt", "w") as gnss:
    for line in src:
        d = json.loads(line)
        if d.get("record") != "measurement":
            continue
        f = d["fields"]
        tow = (f["time_ns"] % week_ns) / 1e9  # from the integer: a float of GPS seconds keeps only ~0.1 us
        if d["name"] == "imu":
            imu.write("%.9f %.12e %.12e %.12e %.12e %.12e %.12e\n" % (
                tow, f["delta_theta_x_rad"], f["delta_theta_y_rad"], f["delta_theta_z_rad"],
                f["delta_v_x_mps"], f["delta_v_y_mps"], f["delta_v_z_mps"]))
        elif d["name"] == "gnss_position":
            gnss.write("%.9f %.11f %.11f %.4f %.4f %.4f %.4f\n" % (
                tow, f["lat_deg"], f["lon_deg"], f["height_m"], f["std_n_m"], f["std_e_m"], f["std_d_m"]))
with open(f"{work}/truth.csv") as t:
    first = next(csv.DictReader(t))
start = float(first["time_gps_s"]) % 604800
# KF-GINS' keys (its src/kf_gins.cpp loadConfig): three values per axis, its units.
axes = lambda *v: "[ " + ", ".join(str(x) for x in (v if len(v) == 3 else v * 3)) + " ]"
keys = {
    "imupath": f'"{work}/imu.txt"', "gnsspath": f'"{work}/gnss.txt"', "outputpath": f'"{work}/kf_out"',
    "imudatalen": 7, "imudatarate": 200, "starttime": f"{start:.3f}", "endtime": -1,
    "initpos": axes(first["lat_deg"], first["lon_deg"], first["height_m"]),
    "initvel": axes(first["vn"], first["ve"], first["vd"]),
    "initatt": axes(first["roll_deg"], first["pitch_deg"], first["yaw_deg"]),
    "initgyrbias": axes(0), "initaccbias": axes(0), "initgyrscale": axes(0), "initaccscale": axes(0),
    "initposstd": axes(0.1, 0.1, 0.2), "initvelstd": axes(0.05), "initattstd": axes(0.5, 0.5, 1.0),
}
# The simulated industrial IMU: deg/sqrt(h), m/s/sqrt(h), deg/h, mGal (5 mg), ppm, hours.
noise = {"arw": axes(0.1), "vrw": axes(0.03), "gbstd": axes(20.0), "abstd": axes(5000.0),
         "gsstd": axes(300.0), "asstd": axes(300.0), "corrtime": 1.0}
with open(f"{work}/kf.yaml", "w") as y:
    y.writelines(f"{k}: {v}\n" for k, v in keys.items())
    y.write("imunoise:\n")
    y.writelines(f"  {k}: {v}\n" for k, v in noise.items())
    y.write(f"antlever: {axes(0.8, -0.4, -1.3)}\n")
PY

for i in $(seq "$RUNS"); do
  /usr/bin/time -f "%e" -a -o "$work/kf_times.txt" "$work/KF-GINS" "$work/kf.yaml" >"$work/kf.log"
  /usr/bin/time -f "%e" -a -o "$work/nf_times.txt" \
    "$NAVFUSE" replay "$work/drive.vnb" "$work/wheel.p1log" --rate 0 --fe-out "$work/out.p1log" --quiet
done
python3 - "$work" <<'PY'
import csv, math, statistics, sys
work = sys.argv[1]
kf = [float(l) for l in open(f"{work}/kf_times.txt")]
nf = [float(l) for l in open(f"{work}/nf_times.txt")]
samples = sum(1 for _ in open(f"{work}/imu.txt"))
mk, mn = statistics.median(kf), statistics.median(nf)
print(f"IMU samples: {samples}; {len(kf)} runs each, in turn")
print(f"KF-GINS  median {mk:.3f} s ({samples / mk:,.0f} IMU samples/s)")
print(f"navfuse  median {mn:.3f} s ({samples / mn:,.0f} IMU samples/s)")
print(f"navfuse / KF-GINS rate: {mk / mn:.1f}x")
last = open(f"{work}/kf_out/KF_GINS_Navresult.nav").read().split("\n")[-2].split()
truth = list(csv.DictReader(open(f"{work}/truth.csv")))[-1]
dn = (float(last[2]) - float(truth["lat_deg"])) * math.pi / 180 * 6378137
de = (float(last[3]) - float(truth["lon_deg"])) * math.pi / 180 * 6378137 * math.cos(float(truth["lat_deg"]) * math.pi / 180)
print(f"KF-GINS last position vs truth: {math.hypot(dn, de):.2f} m horizontal")
PY
