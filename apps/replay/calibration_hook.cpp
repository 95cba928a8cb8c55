#include "apps/replay/calibration_hook.hpp"

#include <utility>

namespace navfuse::apps {
namespace {

CalibrationSolver& registered() {
  static CalibrationSolver solver;
  return solver;
}

}  // namespace

void set_calibration_solver(CalibrationSolver solver) { registered() = std::move(solver); }

const CalibrationSolver& calibration_solver() { return registered(); }

}  // namespace navfuse::apps
