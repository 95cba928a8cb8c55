// A core measurement as named fields in display units (degrees, not radians), for the
// `navfuse decode` CSV / JSON-lines output. Names carry their units.
#pragma once

#include "core/measurements/measurements.hpp"
#include "frontends/common/stream_decoder.hpp"

namespace navfuse::apps {

// Fills `record.name` with the measurement kind and `record.fields` with its values.
void measurement_to_record(const Measurement& m, frontends::FrameRecord& record);

}  // namespace navfuse::apps
