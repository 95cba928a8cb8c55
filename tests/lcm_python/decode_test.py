#!/usr/bin/env python3
"""The Python LCM bindings generated at build time decode a pose_t encoded by the C++ bindings to
the same values (fingerprint included). Usage: decode_test.py POSE_BYTES_BINARY PYTHONPATH"""
import json
import struct
import subprocess
import sys

sys.path.insert(0, sys.argv[2])
from navfuse import pose_t  # noqa: E402  (generated; needs the path above)

out = json.loads(subprocess.run([sys.argv[1]], check=True, capture_output=True, text=True).stdout)
pose = pose_t.decode(bytes.fromhex(out["hex"]))
failures = []
for name, expected in out["fields"].items():
    got = getattr(pose, name)
    if isinstance(expected, list):
        # float32 fields went through JSON as the float32 value widened: compare as float32.
        same = len(got) == len(expected) and all(
            g == e or struct.pack("<f", g) == struct.pack("<f", e) for g, e in zip(got, expected))
    else:
        same = got == expected
    if not same:
        failures.append(f"{name}: decoded {got!r}, encoded {expected!r}")
# Re-encoding gives the C++ bytes back: the two bindings agree on the wire format.
if pose.encode().hex() != out["hex"]:
    failures.append("re-encoded bytes differ from the C++ encoding")
if failures:
    print("FAIL:\n  " + "\n  ".join(failures))
    sys.exit(1)
print(f"PASS: {len(out['fields'])} pose_t fields decoded as encoded by C++")
