#!/usr/bin/env python3
"""Decodes a navfuse-written FusionEngine stream with Point One's public Python client
(fusion-engine-client) and compares every message with the values navfuse wrote.

usage: python_compat_check.py STREAM.p1log EXPECTED.json
Exit 0 only when every message is recognised and every listed field matches."""
import json
import math
import sys

from fusion_engine_client.parsers import FusionEngineDecoder


def value_of(msg, name):
    # Composite names for nested values: config_object_<attr>, rates<i>_<attr>.
    if name == "config_object_lever_arm":
        o = msg.config_object
        return [o.x, o.y, o.z]
    if name.startswith("rates0_"):
        return getattr(msg.rates[0], name[len("rates0_"):])
    v = getattr(msg, name)
    if hasattr(v, "seconds"):  # Timestamp
        return v.seconds
    if isinstance(v, (bytes, bytearray)):
        return v.decode("utf-8")
    if hasattr(v, "tolist"):
        v = v.tolist()
        if v and isinstance(v[0], list):  # 3x3 matrices, row-major
            v = [x for row in v for x in row]
    return v


def close(a, b):
    if isinstance(b, list):
        return isinstance(a, list) and len(a) == len(b) and all(close(x, y) for x, y in zip(a, b))
    if isinstance(b, str):
        return str(a) == b
    a = float(int(a)) if hasattr(a, "value") else float(a)
    return math.isclose(a, float(b), rel_tol=1e-6, abs_tol=1e-6)


def main():
    stream, expected_path = sys.argv[1], sys.argv[2]
    expected = json.load(open(expected_path))
    decoded = []
    decoder = FusionEngineDecoder(warn_on_unrecognized=True, return_bytes=False)
    for header, msg in decoder.on_data(open(stream, "rb").read()):
        decoded.append((header, msg))
    failures = 0
    if len(decoded) != len(expected):
        print(f"decoded {len(decoded)} messages, expected {len(expected)}")
        failures += 1
    for (header, msg), exp in zip(decoded, expected):
        if int(header.message_type) != exp["type"] or msg is None or isinstance(msg, (bytes, bytearray)):
            print(f"type {exp['type']}: not recognised (got {header.message_type})")
            failures += 1
            continue
        for name, want in exp["fields"].items():
            try:
                got = value_of(msg, name)
            except Exception as e:  # noqa: BLE001 - report every problem, then fail
                print(f"{header.message_type}: {name}: {e}")
                failures += 1
                continue
            if not close(got, want):
                print(f"{header.message_type}: {name}: got {got}, expected {want}")
                failures += 1
    print(f"{len(decoded)} messages decoded, {failures} mismatches")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
