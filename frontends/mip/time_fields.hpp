// Writing the shared timestamp fields from a measurement header (digest §4.5): GPS time as
// (0xFF,0xD3) tow/week with both valid bits, a device-monotonic time as (0xFF,0xD5) reference ns.
#pragma once

#include "core/measurements/measurements.hpp"
#include "frontends/mip/writer.hpp"

namespace navfuse::frontends::mip {

void write_time_fields(const MeasurementHeader& h, PacketWriter& w);
// The (0xFF,0xD3) field alone; valid flags 0 when `valid` is false.
void write_gps_timestamp(std::int64_t gps_ns, bool valid, PacketWriter& w);

}  // namespace navfuse::frontends::mip
