#!/usr/bin/env bash
# navfuse's FusionEngine framer against Point One's own parser (PyPI fusion-engine-client) on the
# same bytes: navfuse_fe_bench's 200 MB stream with 1 % of its bytes corrupted, written to a file
# (navfuse_fe_bench_stream write). Issue 15's goal: corrupted-input throughput at least the
# vendor's. Every figure is in-process, from opening the file to the end of the stream, the file
# read in 64 KiB chunks and fed as a link reader would (process start and Python imports
# excluded), the median of RUNS runs, MB = 10^6 bytes:
#   navfuse framer        Framer alone (CRC-checked frames, counted per type);
#   navfuse decoder       FusionEngineDecoder: framing + decoding into measurements;
#   vendor decoder        FusionEngineDecoder.on_data() (framing + its payload deserialisation),
#                         max_payload_len_bytes = 64 KiB (navfuse's bound for unknown types) and
#                         flushed at the end (fe_vendor_count.py --flush), so both framers see the
#                         same frames; with the client's default bound (16 MiB) it waits for every
#                         corrupted size claim and then moves its whole buffer per byte skipped:
#                         FE_VENDOR_DEFAULT_BOUND=S also runs that once, stopped after S seconds,
#                         and prints how many bytes it was handed and how many frames it found;
#   vendor index          fast_generate_index() on one process: numpy sync search + header CRC,
#                         framing only (it does not check the reserved bytes; see its count).
# Valid frames per type are printed for each and compared with navfuse's framer.
#
# Usage: tests/bench/fe_vendor_compare.sh [BUILD_DIR] [RUNS]     (default build/release, 3)
# FE_VENDOR_VENV=DIR uses an existing virtualenv with fusion-engine-client instead of creating
# one in the scratch folder; without it, and without pip or PyPI, the script prints "skipped".
set -euo pipefail
BUILD_DIR=${1:-build/release}
RUNS=${2:-3}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/vendor_compare_lib.sh"
counter="$here/../frontends/fusionengine/fe_vendor_count.py"
tool="$BUILD_DIR/tests/bench/navfuse_fe_bench_stream"
[ -x "$tool" ] || { echo "fe_vendor_compare: $tool not found (build the navfuse_fe_bench_stream target)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

venv=${FE_VENDOR_VENV:-$work/venv}
if [ -z "${FE_VENDOR_VENV:-}" ]; then
  if ! python3 -m venv "$venv" >"$work/pip.log" 2>&1 ||
     ! "$venv/bin/pip" install --quiet fusion-engine-client >>"$work/pip.log" 2>&1; then
    echo "skipped: could not create a virtualenv with fusion-engine-client (no python3 venv, pip or PyPI):"
    tail -3 "$work/pip.log"
    exit 0
  fi
fi
py="$venv/bin/python"
"$py" "$counter" --help >/dev/null 2>&1 || {
  echo "skipped: $py cannot import fusion_engine_client"
  exit 0
}
echo "fusion-engine-client $("$py" -m pip show fusion-engine-client 2>/dev/null | sed -n 's/^Version: //p'), $("$py" --version)"

stream="$work/fe_corrupted.p1log"
"$tool" write "$stream" >/dev/null
echo "stream: $(stat -c %s "$stream") bytes (navfuse_fe_bench's ImuPose stream, 1 % corrupted); $RUNS runs each"

run "navfuse framer" "$work/nf_frame.txt" "$tool" frame "$stream" --runs "$RUNS"
run "navfuse decoder" "$work/nf_decode.txt" "$tool" frame "$stream" --decode --runs "$RUNS"
run "vendor decoder" "$work/fe_decoder.txt" "$py" "$counter" "$stream" --runs "$RUNS" --max-payload 65536 --flush
run "vendor index" "$work/fe_index.txt" "$py" "$counter" "$stream" --runs "$RUNS" --parser index
if [ -n "${FE_VENDOR_DEFAULT_BOUND:-}" ]; then
  run "vendor decoder*" "$work/fe_default.txt" "$py" "$counter" "$stream" --time-limit "$FE_VENDOR_DEFAULT_BOUND"
  fed=$(awk '$1 == "fed_bytes" {print $2}' "$work/fe_default.txt")
  echo "  * the client's default max_payload_len_bytes (16 MiB), one run, no flush, stopped after" \
    "${FE_VENDOR_DEFAULT_BOUND} s: handed ${fed:-all $(stat -c %s "$stream")} bytes" \
    "(the rate is over those; up to 16 MiB of them may still wait in its buffer)"
fi

echo "valid frames per message type (navfuse framer | vendor decoder | vendor index):"
join -j 2 -a 1 -a 2 -e - -o 0,1.3,2.3 <(types "$work/nf_frame.txt") <(types "$work/fe_decoder.txt") |
  join -a 1 -a 2 -e - -o 0,1.2,1.3,2.2 - <(types "$work/fe_index.txt" | cut -d' ' -f2-) |
  awk '{printf "  type %-6s %9s | %9s | %9s\n", $1, $2, $3, $4}'
if cmp -s <(types "$work/nf_frame.txt") <(types "$work/fe_decoder.txt"); then
  echo "navfuse and the vendor decoder found the same frames per type"
else
  echo "navfuse and the vendor decoder DIFFER per type"
fi
echo "vendor index: $(awk '$1 == "reserved_nonzero" {print $2}' "$work/fe_index.txt") of its frames have non-zero reserved bytes (not CRC-covered), which navfuse and the vendor decoder drop"
