// The simulator loop: truth nodes, sensor epochs and the delivery-ordered output queue.
#include "apps/sim/simulator.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/time/gps_time.hpp"

namespace navfuse::sim {
namespace {

// First multiple of `period_ns` at or after `t_ns` (GPS-time grids: a receiver's epochs fall on
// whole multiples of its period since the GPS epoch).
std::int64_t grid_at_or_after(std::int64_t t_ns, std::int64_t period_ns) {
  if (period_ns <= 0) return t_ns;
  const std::int64_t r = t_ns % period_ns;
  return r == 0 ? t_ns : t_ns + (period_ns - r);
}

}  // namespace

Simulator::Simulator(const Scenario& scenario)
    : scenario_(scenario),
      trajectory_(scenario.trajectory, scenario.start_time_ns),
      imu_(scenario.imu, scenario.seed),
      gnss_(scenario.gnss, scenario.seed),
      // Its own draws: a second receiver's errors are independent of the first's.
      second_gnss_(scenario.second_gnss, ~scenario.seed),
      wheel_(scenario.wheel, scenario.seed) {
  const std::int64_t period = imu_.period_ns();
  if (period % scenario_.imu.substeps != 0) {
    throw std::invalid_argument("imu.substeps must divide the IMU period in whole nanoseconds");
  }
  substep_ns_ = period / scenario_.imu.substeps;
  imu_count_ = time::nanoseconds(trajectory_.duration_s()) / period;
  end_time_ns_ = scenario_.start_time_ns + imu_count_ * period;

  nodes_.resize(static_cast<std::size_t>(scenario_.imu.substeps) + 1);
  initial_truth_ = trajectory_.initial();
  initial_truth_.gyro_bias_vehicle_rps = imu_.gyro_bias_vehicle_rps();
  initial_truth_.accel_bias_vehicle_mps2 = imu_.accel_bias_vehicle_mps2();
  initial_truth_.gnss_available = gnss_.available(0.0);
  nodes_.back() = initial_truth_;
  imu_truth_ = initial_truth_;
  last_delivery_ns_ = scenario_.start_time_ns;

  next_gnss_ns_ = grid_at_or_after(scenario_.start_time_ns, gnss_.period_ns());
  next_second_gnss_ns_ = grid_at_or_after(scenario_.start_time_ns, second_gnss_.period_ns());
  next_wheel_ns_ = grid_at_or_after(scenario_.start_time_ns, wheel_.period_ns());
  // Enough for every measurement in flight with the longest latency at the highest rates; the
  // queue grows only if a scenario needs more.
  pending_.reserve(1024);
}

double Simulator::seconds_since_start(std::int64_t time_ns) const {
  return time::seconds(time_ns - scenario_.start_time_ns);
}

bool Simulator::next(Measurement& out) {
  for (;;) {
    // Everything due by the latest IMU time can go: later steps only add deliveries after it.
    if (pending_head_ < pending_.size() &&
        pending_[pending_head_].delivery_ns <= imu_truth_.time_ns) {
      Pending& p = pending_[pending_head_++];
      out = p.measurement;
      last_delivery_ns_ = p.delivery_ns;
      return true;
    }
    if (k_ >= imu_count_) return false;  // measurements still in flight are never delivered
    step();
  }
}

void Simulator::push(std::int64_t delivery_ns) {
  // Drop delivered entries once the queue is drained (or mostly drained): no reallocation.
  if (pending_head_ == pending_.size()) {
    pending_.clear();
    pending_head_ = 0;
  } else if (pending_head_ > 256) {
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(pending_head_));
    pending_head_ = 0;
  }
  // Insert after every entry due at or before `delivery_ns`: ties keep generation order.
  const auto pos = std::upper_bound(
      pending_.begin() + static_cast<std::ptrdiff_t>(pending_head_), pending_.end(), delivery_ns,
      [](std::int64_t t, const Pending& p) { return t < p.delivery_ns; });
  pending_.insert(pos, Pending{delivery_ns, order_++, scratch_});
}

TruthSample Simulator::truth_in_interval(std::int64_t time_ns) const {
  // Nearest truth node at or before `time_ns`, then one short RK4 step if it falls between nodes.
  const std::int64_t from = nodes_.front().time_ns;
  std::size_t j = static_cast<std::size_t>(std::max<std::int64_t>(0, (time_ns - from) / substep_ns_));
  j = std::min(j, nodes_.size() - 1);
  const TruthSample& node = nodes_[j];
  return time_ns == node.time_ns ? node : trajectory_.propagate(node, time_ns - node.time_ns);
}

void Simulator::step() {
  const std::size_t n = nodes_.size() - 1;
  nodes_.front() = nodes_.back();
  for (std::size_t j = 1; j <= n; ++j) nodes_[j] = trajectory_.propagate(nodes_[j - 1], substep_ns_);
  ++k_;

  // Truth of this sample: biases as they are in the sample (before the bias process advances).
  imu_truth_ = nodes_.back();
  imu_truth_.gyro_bias_vehicle_rps = imu_.gyro_bias_vehicle_rps();
  imu_truth_.accel_bias_vehicle_mps2 = imu_.accel_bias_vehicle_mps2();
  imu_truth_.gnss_available = gnss_.available(seconds_since_start(imu_truth_.time_ns));

  imu_.make_sample(nodes_.data(), scratch_.emplace<ImuSample>());
  push(imu_truth_.time_ns);
  sensor_events(imu_truth_.time_ns);
}

void Simulator::sensor_events(std::int64_t t_end_ns) {
  // Epochs stamped in (previous IMU time, t_end]; the very first interval also takes the start.
  gnss_events(gnss_, next_gnss_ns_, t_end_ns);
  gnss_events(second_gnss_, next_second_gnss_ns_, t_end_ns);
  while (wheel_.enabled() && next_wheel_ns_ <= t_end_ns) {
    const std::int64_t t = next_wheel_ns_;
    next_wheel_ns_ += wheel_.period_ns();
    const TruthSample truth = truth_in_interval(t);
    const std::int64_t delivery = t + wheel_.latency_ns();
    if (wheel_.spec().vehicle_speed) {
      wheel_.make_vehicle_speed(truth, scratch_.emplace<VehicleSpeed>());
      push(delivery);
    }
    if (wheel_.spec().wheel_speeds) {
      wheel_.make_wheel_speeds(truth, scratch_.emplace<WheelSpeeds>());
      push(delivery);
    }
    wheel_.advance_ticks(truth);
    if (wheel_.spec().wheel_ticks) {
      wheel_.make_wheel_ticks(truth, scratch_.emplace<WheelTicks>());
      push(delivery);
    }
    if (wheel_.spec().vehicle_ticks) {
      wheel_.make_vehicle_ticks(truth, scratch_.emplace<WheelTicks>());
      push(delivery);
    }
  }
}

void Simulator::gnss_events(GnssModel& gnss, std::int64_t& next_ns, std::int64_t t_end_ns) {
  while (gnss.spec().enabled && next_ns <= t_end_ns) {
    const std::int64_t t = next_ns;
    next_ns += gnss.period_ns();
    const TruthSample truth = truth_in_interval(t);
    const GnssModel::Epoch epoch =
        gnss.make_epoch(truth, seconds_since_start(t), gnss_pos_, gnss_vel_, gnss_heading_);
    const std::int64_t delivery = t + gnss.latency_ns();
    if (epoch.has_position) {
      scratch_ = gnss_pos_;
      push(delivery);
    }
    if (epoch.has_velocity) {
      scratch_ = gnss_vel_;
      push(delivery);
    }
    if (epoch.has_heading) {
      scratch_ = gnss_heading_;
      push(delivery);
    }
  }
}

SimulationOutput simulate(const Scenario& scenario) {
  Simulator sim(scenario);
  SimulationOutput out;
  out.initial_truth = sim.initial_truth();
  out.truth.reserve(static_cast<std::size_t>(sim.imu_sample_count()));
  out.measurements.reserve(static_cast<std::size_t>(sim.imu_sample_count()) * 5 / 4 + 16);
  out.delivery_time_ns.reserve(out.measurements.capacity());
  Measurement m;
  while (sim.next(m)) {
    if (kind_of(m) == MeasurementKind::kImu) out.truth.push_back(sim.truth());
    out.measurements.push_back(m);
    out.delivery_time_ns.push_back(sim.delivery_time_ns());
  }
  return out;
}

const TruthSample* find_truth(const std::vector<TruthSample>& truth, std::int64_t time_ns) {
  const auto it = std::upper_bound(truth.begin(), truth.end(), time_ns,
                                   [](std::int64_t t, const TruthSample& s) { return t < s.time_ns; });
  return it == truth.begin() ? nullptr : &*(it - 1);
}

}  // namespace navfuse::sim
