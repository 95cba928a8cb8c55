// The calibration solver as navfuse_apps sees it: a function the navfuse executable registers
// (apps/main.cpp, with calib::calibrate from navfuse_calibration), so Ceres is linked by the
// calibration library and the executable only, not by everything that links the app library.
// Tests that calibrate register it the same way.
#pragma once

#include <functional>

#include "calibration/calibration_log.hpp"
#include "calibration/calibration_result.hpp"

namespace navfuse::apps {

using CalibrationSolver = std::function<calib::CalibrationResult(const calib::CalibrationLog&)>;

void set_calibration_solver(CalibrationSolver solver);
// Empty when none was registered.
const CalibrationSolver& calibration_solver();

}  // namespace navfuse::apps
