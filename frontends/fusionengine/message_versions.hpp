// Older message versions on the wire. "New versions ... maintain backwards compatibility by
// either using previously reserved space in older version definitions or by extending the
// message length" (spec L189): a newer payload decodes with the known layout (its extra bytes
// ignored), while an older payload may leave fields of the current layout unset.
//
// After a payload has been decoded with the current layout, adapt_to_version() clears what the
// frame's older version did not carry, or returns false when that version's layout is not the
// one the spec defines (then the frame is a decode error, not a misread).
#pragma once

#include <cstdint>

#include "frontends/fusionengine/messages_solution.hpp"

namespace navfuse::frontends::fusionengine {

// Pose: undulation was "added in PoseMessage version 1.1" and flags "in version 1.2" (L1735-1736;
// "1.N" is wire version N, digest §13 B13). Version 0 senders leave that space reserved (zero),
// which must not read as a valid 0 cm undulation.
inline bool adapt_to_version(PoseMessage& m, std::uint8_t version) {
  if (version < 1) m.undulation_cm = kInvalidUndulationCm;
  if (version < 2) m.flags = 0;
  return true;
}

// GNSSInfo: the spec defines version 1, "revised (leap s, #SV, corrections age, baseline)" in doc
// v0.15 (L3081); version 0 has another layout that the spec does not give, so it is not decoded.
inline bool adapt_to_version(GnssInfoMessage&, std::uint8_t version) { return version >= 1; }

// Every other message: one layout for all versions seen so far.
template <class M>
bool adapt_to_version(M&, std::uint8_t) {
  return true;
}

}  // namespace navfuse::frontends::fusionengine
