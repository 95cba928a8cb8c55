#include "apps/replay/smoothed_pass.hpp"

#include <stdexcept>

#include <chrono>
#include <optional>

#include "apps/common/command_error.hpp"
#include "apps/output/output_rate.hpp"
#include "apps/output/pose_output_thread.hpp"

namespace navfuse::apps {

std::unique_ptr<filter::ForwardRecorder> record_forward_pass(filter::Engine& engine) {
  std::unique_ptr<filter::ForwardRecorder> record;
  try {
    record = std::make_unique<filter::ForwardRecorder>();
  } catch (const std::runtime_error& e) {
    throw CommandError(e.what());
  }
  engine.record_to(record.get());
  return record;
}

SmoothedPassResult write_smoothed(filter::ForwardRecorder& record, const filter::FilterOptions& options,
                                  TimeSource time_source, double rate_hz, PoseOutputs& outputs,
                                  TruthAccuracy* accuracy,
                                  const std::function<void(const filter::SmoothedSample&)>& also) {
  SmoothedPassResult result;
  const auto start = std::chrono::steady_clock::now();
  std::optional<PoseOutputThread> writer;
  if (!outputs.empty()) writer.emplace(outputs);
  OutputRate rate(rate_hz);
  OutputEpoch epoch;
  result.stats = filter::smooth(record, [&](const filter::SmoothedSample& s) {
    epoch.solution = filter::smoothed_solution(s, options, time_source);
    epoch.pose_due = rate.due(s.x.time_ns);
    if (epoch.pose_due) {
      ++result.poses;
      const NavMode mode = epoch.solution.mode;
      if (mode == NavMode::kSmoothed || mode == NavMode::kNavigation || mode == NavMode::kDeadReckoning) {
        ++result.navigating_poses;
      }
    }
    if (writer) writer->post(epoch);
    if (accuracy != nullptr && epoch.pose_due) accuracy->add(epoch.solution);
    if (also) also(s);
  });
  if (writer) writer->finish();
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result.stats.error.empty()) throw CommandError("smoothing failed: " + result.stats.error);
  return result;
}

}  // namespace navfuse::apps
