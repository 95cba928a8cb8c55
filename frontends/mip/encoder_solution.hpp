// Writes a navfuse NavSolution as the MIP filter packets (set 0x82) a CV7 would stream, so
// software written for a CV7 consumes navfuse (issue #4; DESIGN.md --mip-out).
//
// Fields, in this order: (0xFF,0xD3) GPS timestamp, 0x10 status, 0x01 LLH, 0x02 NED velocity,
// 0x03 quaternion, 0x05 Euler, 0x06 gyro bias, 0x07 accel bias, 0x08 / 0x09 / 0x0A position,
// velocity and Euler uncertainties, 0x0B / 0x0C bias uncertainties, 0x0D linear acceleration,
// 0x0E compensated angular rate, 0x13 gravity vector (vehicle frame). They exceed the 255-byte
// payload limit, so the output is split on a field boundary into a continuation packet that
// repeats the leading timestamp (digest §2.8, L3974-4018).
//
// (0x82,0x17) is not written: the CV7 spec has no MSL-height filter field, and mip_sdk assigns
// 0x17 to accel scale factor; MSL height would need a field the device does not have.
#pragma once

#include <cstdint>
#include <vector>

#include "core/measurements/measurements.hpp"

namespace navfuse::frontends::mip {

// Appends the packet(s) for `s` to `out`. Returns the number of packets written.
std::size_t encode_solution(const NavSolution& s, std::vector<std::uint8_t>& out);

}  // namespace navfuse::frontends::mip
