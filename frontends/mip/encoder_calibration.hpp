// The estimated calibration a CV7 streams in its filter data set 0x82 besides the solution
// (digest §4.2): odometer scale factor error (0x47) and its uncertainty (0x48), and the primary
// antenna's offset correction (0x34) and its uncertainty (0x35, receiver 1), each with its
// valid flag set only while the filter estimates that state (NavSolution::Calibration).
//
// One packet of its own, led by the shared timestamp fields like every 0x82 packet navfuse
// writes (frontends/mip/encoder_solution.hpp), so a reader joins it to that epoch's solution.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/measurements/measurements.hpp"

namespace navfuse::frontends::mip {

// Conventions (digest L4500, L4656):
//  - CV7: "total SF = user SF + user SF * error", the factor from ticks to true distance; navfuse
//    measured = (1 + e) * true, so the CV7 error is 1 / (1 + e) - 1 = -e / (1 + e), its
//    uncertainty std / (1 + e)^2 to first order.
//  - The offset correction is "ADDED to the stored offset": the estimated lever arm minus
//    `configured_lever_arm_m` (vehicle frame, the offset in force on the device).
void encode_calibration(const NavSolution& s, const Eigen::Vector3d& configured_lever_arm_m,
                        std::vector<std::uint8_t>& out);

}  // namespace navfuse::frontends::mip
