#!/usr/bin/env bash
# navfuse's MIP framer against MicroStrain's own C parser (mip_sdk's mip_parser) on the same bytes:
# navfuse_mip_bench's 200 MB CV7-style stream with 1 % of its bytes corrupted, written to a file
# (navfuse_mip_bench_stream write). Issue 15's goal: corrupted-input throughput at least the
# vendor's. Every figure is in-process, from opening the file to the end of the stream, the file
# read in 64 KiB chunks (the read inside the timed span), the median of RUNS runs, MB = 10^6 bytes:
#   navfuse framer    Framer alone (checksum-checked packets whose fields tile the payload);
#   navfuse decoder   MipDecoder: framing + decoding into measurements;
#   vendor parser     mip_parser_parse() into a callback that counts packets per descriptor set
#                     (mip_vendor_count.c), built here with -O3 -DNDEBUG from the SDK's C sources.
# Valid packets per descriptor set are printed for both and compared.
#
# Usage: tests/bench/mip_vendor_compare.sh [BUILD_DIR] [RUNS]     (default build/release, 3)
# MIP_SDK_DIR=DIR uses an mip_sdk checkout (github.com/LORD-MicroStrain/mip_sdk, its C parser
# sources under src/mip); without it the script clones the repository into its scratch folder,
# and prints "skipped" when it cannot (no git or no network).
set -euo pipefail
BUILD_DIR=${1:-build/release}
RUNS=${2:-3}
here=$(cd "$(dirname "$0")" && pwd)
source "$here/vendor_compare_lib.sh"
tool="$BUILD_DIR/tests/bench/navfuse_mip_bench_stream"
[ -x "$tool" ] || { echo "mip_vendor_compare: $tool not found (build the navfuse_mip_bench_stream target)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

sdk=${MIP_SDK_DIR:-$work/mip_sdk}
if [ -z "${MIP_SDK_DIR:-}" ] &&
   ! git clone --quiet --depth 1 https://github.com/LORD-MicroStrain/mip_sdk "$sdk" >"$work/git.log" 2>&1; then
  echo "skipped: could not clone mip_sdk (set MIP_SDK_DIR to a checkout):"
  tail -2 "$work/git.log"
  exit 0
fi
# The parser and what it links: the packet and field checks, the byte ring, and the descriptor
# helpers the packet code calls.
src="$sdk/src/mip"
sources=("$src/mip_parser.c" "$src/mip_packet.c" "$src/mip_field.c" "$src/utils/byte_ring.c"
         "$src/utils/serialization.c" "$src/definitions/descriptors.c")
for f in "${sources[@]}"; do
  [ -f "$f" ] || { echo "skipped: $f not found (an mip_sdk checkout with the C parser under src/mip?)"; exit 0; }
done
if ! cc -std=gnu99 -O3 -DNDEBUG -I"$sdk/src" -I"$src" "$here/mip_vendor_count.c" "${sources[@]}" \
     -o "$work/mip_vendor_count" 2>"$work/cc.log"; then
  echo "skipped: the vendor parser did not build against $sdk:"
  head -5 "$work/cc.log"
  exit 0
fi
echo "mip_sdk at $sdk$(git -C "$sdk" rev-parse --short HEAD 2>/dev/null | sed 's/^/ (commit /;s/$/)/' || true)"

stream="$work/mip_corrupted.bin"
"$tool" write "$stream" >/dev/null
echo "stream: $(stat -c %s "$stream") bytes (navfuse_mip_bench's CV7-style stream, 1 % corrupted); $RUNS runs each"

run "navfuse framer" "$work/nf_frame.txt" "$tool" frame "$stream" --runs "$RUNS"
run "navfuse decoder" "$work/nf_decode.txt" "$tool" frame "$stream" --decode --runs "$RUNS"
run "vendor parser" "$work/vendor.txt" "$work/mip_vendor_count" "$stream" "$RUNS"

echo "valid packets per descriptor set (navfuse framer | vendor parser):"
join -j 2 -a 1 -a 2 -e - -o 0,1.3,2.3 <(types "$work/nf_frame.txt") <(types "$work/vendor.txt") |
  awk '{printf "  set 0x%02x %9s | %9s\n", $1, $2, $3}'
if cmp -s <(types "$work/nf_frame.txt") <(types "$work/vendor.txt"); then
  echo "navfuse and the vendor parser found the same packets per descriptor set"
else
  echo "navfuse and the vendor parser DIFFER per descriptor set: the parser checks the checksum only," \
    "navfuse also that the fields tile the payload (MIP packet structure), so a corrupted packet whose" \
    "Fletcher checksum matches by chance (1 in 65,536) is the vendor's alone"
fi
