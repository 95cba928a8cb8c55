#!/usr/bin/env python3
"""Frames a FusionEngine file with Point One's own Python client (PyPI fusion-engine-client) and
prints the valid frames per message type, in the format navfuse_fe_bench_stream prints:
"type T N" lines, "frames N", then "median_s S mb_per_s R" (MB = 10^6 bytes; the time runs from
opening the file to the end of the stream, in-process, interpreter start and imports excluded).

usage: fe_vendor_count.py FILE [--parser decoder|index] [--runs N] [--chunk BYTES]
                           [--max-payload BYTES] [--flush] [--time-limit S]
  decoder  FusionEngineDecoder.on_data(), the client's streaming framer + decoder (it always
           deserializes the payload of a known type), fed chunks of BYTES (default 65536) as
           read from the file, as a link reader would hand them over. --max-payload is its
           max_payload_len_bytes (the client's default: 16 MiB): a header claiming more is
           dropped at once, a smaller claim is waited for before its CRC is checked. The client
           has no end-of-stream call, so a claim still waited for at the end hides the frames
           behind it; --flush then feeds max-payload + 24 zero bytes (they hold no sync byte),
           which completes that claim, fails its CRC and lets the rest be rescanned, as
           navfuse's Framer::finish() does. The flush is inside the timed span. --time-limit
           stops feeding after the chunk that ends past S seconds (one run): "fed_bytes N"
           then gives how far it got, and the rate is over those bytes.
  index    fast_generate_index() on one process (num_threads=1), the client's fastest file
           scan: sync search in numpy, header + CRC check per candidate, no index file written.
           It only sees messages of at most 16 KiB (its _MAX_FE_MSG_SIZE_BYTES), and it does
           not check the header's reserved bytes (outside the CRC), which the decoder and
           navfuse require to be zero: "reserved_nonzero N" counts the frames it found with
           them non-zero (checked after the timed runs).
Exits 3 when fusion_engine_client cannot be imported (callers treat it as "skipped")."""
import argparse
import collections
import contextlib
import os
import statistics
import sys
import time

# The client's leap-second table (gpstime) has expired; it refuses to import without this, and
# prints its attempts to download a new one, kept out of the counts printed here.
os.environ.setdefault("GPSTIME_ALLOW_EXPIRED", "1")
try:
    with open(os.devnull, "w") as quiet, contextlib.redirect_stdout(quiet), contextlib.redirect_stderr(quiet):
        import warnings
        warnings.simplefilter("ignore")
        from fusion_engine_client.parsers import FusionEngineDecoder
        from fusion_engine_client.parsers.fast_indexer import fast_generate_index
except Exception as e:  # noqa: BLE001 - any import failure means the client is unusable here
    print(f"skipped: cannot import fusion_engine_client ({e})")
    sys.exit(3)


def count_with_decoder(path, args):
    counts = collections.Counter()
    # Warnings off: a corrupted stream would print one per CRC failure of a plausible header.
    decoder = FusionEngineDecoder(max_payload_len_bytes=args.max_payload, warn_on_error=False)

    def take(data):
        for header, _payload in decoder.on_data(data):
            counts[int(header.message_type)] += 1

    t0 = time.perf_counter()
    with open(path, "rb") as f:
        while True:
            data = f.read(args.chunk)
            if not data:
                break
            take(data)
            args.fed_bytes += len(data)
            if args.time_limit and time.perf_counter() - t0 > args.time_limit:
                return counts, None
    if args.flush:
        take(bytes(args.max_payload + 24))
    return counts, None


def count_with_index(path, _args):
    index = fast_generate_index(path, force_reindex=True, save_index=False, num_threads=1)
    return collections.Counter(int(t) for t in index.type), index


def reserved_nonzero(path, index):
    n = 0
    with open(path, "rb") as f:
        for offset in index.offset:
            f.seek(int(offset) + 2)
            n += f.read(2) != b"\0\0"
    return n


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("file")
    ap.add_argument("--parser", choices=["decoder", "index"], default="decoder")
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--chunk", type=int, default=65536)
    ap.add_argument("--max-payload", type=int, default=1 << 24)
    ap.add_argument("--flush", action="store_true")
    ap.add_argument("--time-limit", type=float, default=0.0)
    args = ap.parse_args()
    count = count_with_decoder if args.parser == "decoder" else count_with_index
    times = []
    counts = index = None
    for _ in range(1 if args.time_limit else max(1, args.runs)):
        args.fed_bytes = 0
        t0 = time.perf_counter()
        counts, index = count(args.file, args)
        times.append(time.perf_counter() - t0)
    for t in sorted(counts):
        print(f"type {t} {counts[t]}")
    print(f"frames {sum(counts.values())}")
    if index is not None:
        print(f"reserved_nonzero {reserved_nonzero(args.file, index)}")
    size = os.path.getsize(args.file)
    if args.time_limit and args.fed_bytes < size:
        print(f"fed_bytes {args.fed_bytes}")
        size = args.fed_bytes
    median = statistics.median(times)
    print(f"median_s {median:.4f} mb_per_s {size / median / 1e6:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
