// Mapping between the CV7 filter status (0x82,0x10: filter_state, dynamics_mode, status_flags;
// digest §6.2-§6.3, L622-706, L4363-4416) and navfuse's NavMode / NavSolution status bits.
//
// filter_state 1 INIT, 2 VERT_GYRO, 3 AHRS, 4 FULL_NAV map one to one onto NavMode
// kInitializing, kVerticalGyro, kAhrs, kNavigation (errata E36: the GX5 values are ignored).
// MIP has no dead-reckoning state: navfuse's kDeadReckoning is sent as FULL_NAV with the position
// and velocity warnings raised (bits 4, 5: its absolute aiding is gone), and read back as such.
// Condition (bits 0-1): 3 unstable/recovering (errata E15) or any solution-error bit 12-15
// (errata E16) mean diverged; navfuse sends 2 "converging" while initialising, else 1 "stable".
#pragma once

#include <cstdint>

#include "core/measurements/measurements.hpp"

namespace navfuse::frontends::mip {

struct FilterStatusWord {
  std::uint16_t filter_state = 0;
  std::uint16_t dynamics_mode = 0;
  std::uint16_t status_flags = 0;
};

FilterStatusWord status_from_solution(const NavSolution& s);
// Sets mode, status_flags and device_status ((filter_state << 16) | status_flags) of `s`.
// Returns false when the solution-error bits say all outputs are invalid (L672, L706-708).
bool apply_status(const FilterStatusWord& w, NavSolution& s);

}  // namespace navfuse::frontends::mip
