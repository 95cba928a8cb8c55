#!/usr/bin/env bash
# Peak memory of `navfuse bench` against `navfuse replay` on a ~1 GB log (issue 15.10: bench must
# stream like replay, its memory flat in the input size). The log is the drive_8h scenario as a
# VN-300 log with the device's own INS solution at its default rate, made by `navfuse sim` in a temporary
# folder (WORK, default a fresh folder under /tmp; never commit it). Peak RSS is /usr/bin/time's
# "Maximum resident set size". Not a timed test: run it by hand and quote the figures in README.
#
# Usage: tests/bench/bench_memory.sh [BUILD_DIR] [WORK]     (default build/release)
set -euo pipefail
BUILD_DIR=${1:-build/release}
NAVFUSE="$BUILD_DIR/apps/navfuse"
[ -x "$NAVFUSE" ] || { echo "bench_memory: $NAVFUSE not found (build first)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "bench_memory: /usr/bin/time missing (apt-get install time)" >&2; exit 1; }
work=${2:-}
if [ -z "$work" ]; then
  work=$(mktemp -d /tmp/navfuse_bench_memory.XXXXXX)
  trap 'rm -rf "$work"' EXIT
fi

log="$work/drive_8h.vnb"
[ -s "$log" ] || "$NAVFUSE" sim --scenario drive_8h --format vn --out "$log" --quiet
log_mb=$(( $(stat -c %s "$log") / 1048576 ))

peak_mb() {  # peak RSS in MB of the command given
  /usr/bin/time -f "%M" -o "$work/rss.txt" "$@" > /dev/null
  echo $(( $(tail -1 "$work/rss.txt") / 1024 ))
}
replay_mb=$(peak_mb "$NAVFUSE" replay "$log" --csv "$work/poses.csv" --quiet)
bench_mb=$(peak_mb "$NAVFUSE" bench "$log" --report "$work/report" --no-html --quiet)
echo "log: $log_mb MB (drive_8h, vn)"
echo "peak RSS: replay $replay_mb MB, bench $bench_mb MB (bench / replay = $(python3 -c "print(f'{$bench_mb / $replay_mb:.1f}')"))"
