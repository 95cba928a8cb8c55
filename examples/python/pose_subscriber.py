#!/usr/bin/env python3
"""Prints the poses navfuse publishes on NAVFUSE_POSE over LCM, one line each.

The message types are generated from core/lcm/*.lcm at build time (lcm-gen --python) into
<build>/generated/lcm-python; LCM's own Python module is Debian's python3-lcm where the
distribution has it, else PyPI's `lcm` (pip install lcm; Debian 12 has no python3-lcm). For
example, with `navfuse run ... --lcm` or `navfuse replay ... --lcm` publishing:

    PYTHONPATH=build/release/generated/lcm-python python3 examples/python/pose_subscriber.py
    PYTHONPATH=... python3 examples/python/pose_subscriber.py --url 'udpm://239.255.76.67:7667?ttl=0' --count 10
    PYTHONPATH=... python3 examples/python/pose_subscriber.py --mode navigation
"""
import argparse
import sys

import lcm

from navfuse import pose_t

CHANNEL = "NAVFUSE_POSE"  # apps/lcm/lcm_channels.hpp
# navfuse::NavMode (core/measurements/measurements.hpp), by value.
MODES = ["invalid", "initializing", "vertical_gyro", "ahrs", "navigation", "dead_reckoning"]


def describe(pose):
    mode = MODES[pose.mode] if 0 <= pose.mode < len(MODES) else f"mode {pose.mode}"
    roll, pitch, yaw = pose.rpy_deg
    return (f"{pose.time_gps_ns * 1e-9:.3f} {mode:>14} lat {pose.lat_deg:.7f} lon {pose.lon_deg:.7f} "
            f"h {pose.height_m:.2f} m  vel NED {pose.vel_ned_mps[0]:.2f} {pose.vel_ned_mps[1]:.2f} "
            f"{pose.vel_ned_mps[2]:.2f} m/s  rpy {roll:.1f} {pitch:.1f} {yaw:.1f} deg")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--url", help="LCM URL (default: LCM_DEFAULT_URL, else LCM's udpm default)")
    parser.add_argument("--count", type=int, default=0, help="exit after this many poses (default: run until Ctrl-C)")
    parser.add_argument("--timeout", type=float, default=0.0,
                        help="exit with status 1 when no pose came for this many seconds (default: wait forever)")
    parser.add_argument("--mode", choices=MODES, help="print (and count) only poses in this mode")
    args = parser.parse_args()

    lc = lcm.LCM(args.url) if args.url else lcm.LCM()
    received = 0

    def on_pose(_channel, data):
        nonlocal received
        pose = pose_t.decode(data)
        if args.mode and (pose.mode >= len(MODES) or MODES[pose.mode] != args.mode):
            return
        print(describe(pose), flush=True)
        received += 1

    lc.subscribe(CHANNEL, on_pose)
    wait_ms = int(args.timeout * 1000) if args.timeout > 0 else 1000
    try:
        while args.count == 0 or received < args.count:
            if lc.handle_timeout(wait_ms) == 0 and args.timeout > 0:
                print(f"no pose on {CHANNEL} for {args.timeout} s", file=sys.stderr)
                return 1
    except KeyboardInterrupt:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
