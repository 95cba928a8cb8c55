#include "filter/smoother/forward_record.hpp"

#include <cstring>
#include <stdexcept>

#include <unistd.h>

#include "core/rotation/rotation.hpp"
#include "filter/process_model.hpp"
#include "filter/solution.hpp"

namespace navfuse::filter {
namespace {

constexpr std::size_t kHeaderBytes = 1 + sizeof(std::uint32_t);  // type, payload length

// Little serialisation helpers: host byte order (the file never leaves this process).
class Out {
 public:
  explicit Out(std::vector<unsigned char>& b) : b_(b) { b_.clear(); }
  template <class T>
  void put(T v) {
    const std::size_t at = b_.size();
    b_.resize(at + sizeof(T));
    std::memcpy(b_.data() + at, &v, sizeof(T));
  }
  void put(const Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) put(v(i));
  }
  void put(const NavState& x) {
    put(x.time_ns);
    put(x.lat_rad);
    put(x.lon_rad);
    put(x.height_m);
    put(x.vel_ned_mps);
    put(x.q_nb.w());
    put(x.q_nb.x());
    put(x.q_nb.y());
    put(x.q_nb.z());
    put(x.gyro_bias_rps);
    put(x.accel_bias_mps2);
    put(x.gyro_scale);
    put(x.accel_scale);
    put(x.wheel_scale);
    put(x.mount_pitch_rad);
    put(x.mount_yaw_rad);
    put(x.gnss_lever_arm_m);
    put(x.gnss_time_offset_s);
  }
  // Upper triangle of the leading n x n block.
  void put_symmetric(const Covariance& p, int n) {
    for (int c = 0; c < n; ++c) {
      for (int r = 0; r <= c; ++r) put(p(r, c));
    }
  }

 private:
  std::vector<unsigned char>& b_;
};

class In {
 public:
  In(const std::vector<unsigned char>& b) : b_(b) {}
  template <class T>
  T get() {
    T v{};
    if (at_ + sizeof(T) > b_.size()) {
      short_ = true;
      return v;
    }
    std::memcpy(&v, b_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  Eigen::Vector3d vec() {
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) v(i) = get<double>();
    return v;
  }
  NavState state() {
    NavState x;
    x.time_ns = get<std::int64_t>();
    x.lat_rad = get<double>();
    x.lon_rad = get<double>();
    x.height_m = get<double>();
    x.vel_ned_mps = vec();
    const double w = get<double>(), qx = get<double>(), qy = get<double>(), qz = get<double>();
    x.q_nb = Eigen::Quaterniond(w, qx, qy, qz);
    x.gyro_bias_rps = vec();
    x.accel_bias_mps2 = vec();
    x.gyro_scale = vec();
    x.accel_scale = vec();
    x.wheel_scale = get<double>();
    x.mount_pitch_rad = get<double>();
    x.mount_yaw_rad = get<double>();
    x.gnss_lever_arm_m = vec();
    x.gnss_time_offset_s = get<double>();
    return x;
  }
  void symmetric(Covariance& p, int n) {
    p.setZero();
    for (int c = 0; c < n; ++c) {
      for (int r = 0; r <= c; ++r) p(r, c) = p(c, r) = get<double>();
    }
  }
  bool short_read() const { return short_; }

 private:
  const std::vector<unsigned char>& b_;
  std::size_t at_ = 0;
  bool short_ = false;
};

bool same_state(const NavState& a, const NavState& b) {
  return a.time_ns == b.time_ns && a.lat_rad == b.lat_rad && a.lon_rad == b.lon_rad && a.height_m == b.height_m &&
         a.vel_ned_mps == b.vel_ned_mps && a.q_nb.coeffs() == b.q_nb.coeffs() &&
         a.gyro_bias_rps == b.gyro_bias_rps && a.accel_bias_mps2 == b.accel_bias_mps2 &&
         a.gyro_scale == b.gyro_scale && a.accel_scale == b.accel_scale && a.wheel_scale == b.wheel_scale &&
         a.mount_pitch_rad == b.mount_pitch_rad && a.mount_yaw_rad == b.mount_yaw_rad &&
         a.gnss_lever_arm_m == b.gnss_lever_arm_m && a.gnss_time_offset_s == b.gnss_time_offset_s;
}

// Payload scratch shared by the hooks (the filter is single-threaded per recorder).
thread_local std::vector<unsigned char> scratch;

void emit(FilterCore& c, RecordType type) { c.record.sink->write(c.record.next_index++, type, scratch); }

// kIntervalStart / kClose: the state and covariance `p` a covariance step starts from.
// kIntervalStart / kClose: the node's flags byte.
constexpr std::uint8_t kNodeNavigating = 0x01;
constexpr std::uint8_t kNodeInflationAfterOutage = 0x02;

void put_node(Out& out, const FilterCore& c, const Covariance& p, bool inflation_after_outage = false) {
  out.put(c.x.time_ns);
  out.put(static_cast<std::int32_t>(c.ekf.n));
  out.put(static_cast<std::uint8_t>((c.navigating() ? kNodeNavigating : 0) |
                                    (inflation_after_outage ? kNodeInflationAfterOutage : 0)));
  out.put(c.x);
  out.put_symmetric(p, c.ekf.n);
}

// kPropagation: the prior state, covariance and the rows of the transition matrix with dynamics.
void put_prior(Out& out, const FilterCore& c, const SystemRows& phi_rows) {
  out.put(c.x.time_ns);
  out.put(static_cast<std::int32_t>(c.ekf.n));
  out.put(c.x);
  out.put_symmetric(c.ekf.p, c.ekf.n);
  for (int r = 0; r < sx::kDynamicCount; ++r) {
    for (int col = 0; col < c.ekf.n; ++col) out.put(phi_rows(r, col));
  }
}

}  // namespace

ForwardRecorder::ForwardRecorder() : file_(std::tmpfile()) {
  if (file_ == nullptr) throw std::runtime_error("cannot create a temporary file for the forward record");
  std::setvbuf(file_, nullptr, _IOFBF, 1 << 20);
}

ForwardRecorder::~ForwardRecorder() {
  if (file_ != nullptr) std::fclose(file_);
}

void ForwardRecorder::fail(const std::string& what) {
  if (error_.empty()) error_ = what;
}

void ForwardRecorder::write(std::uint64_t index, RecordType type, const std::vector<unsigned char>& payload) {
  if (index > offsets_.size()) {
    fail("forward record index " + std::to_string(index) + " beyond the " + std::to_string(offsets_.size()) +
         " records written");
    return;
  }
  if (index < offsets_.size()) {
    replaced_ += offsets_.size() - index;
    end_ = offsets_[index];
    offsets_.resize(index);
    types_.resize(index);
  }
  if (position_ != end_ && fseeko(file_, static_cast<off_t>(end_), SEEK_SET) != 0) {
    fail("seek in the forward record failed");
    return;
  }
  const auto type_byte = static_cast<std::uint8_t>(type);
  const auto length = static_cast<std::uint32_t>(payload.size());
  unflushed_ = true;
  const bool ok = std::fwrite(&type_byte, 1, 1, file_) == 1 && std::fwrite(&length, sizeof length, 1, file_) == 1 &&
                  (payload.empty() || std::fwrite(payload.data(), 1, payload.size(), file_) == payload.size());
  if (!ok) {
    fail("writing the forward record failed (disk full?)");
    position_ = UINT64_MAX;
    return;
  }
  offsets_.push_back(end_);
  types_.push_back(type);
  end_ += kHeaderBytes + payload.size();
  position_ = end_;
}

void ForwardRecorder::close(const FilterCore& core) {
  Out out(scratch);
  put_node(out, core, core.ekf.p);
  write(core.record.next_index, RecordType::kClose, scratch);
}

bool ForwardRecorder::read(std::size_t i, ForwardRecordEntry& e) {
  if (i >= offsets_.size()) return false;
  // Random access by pread on the descriptor: stdio's buffer would refill a whole megabyte for
  // every record the backward pass reads. Written bytes still in that buffer are flushed first.
  if (unflushed_) {
    if (std::fflush(file_) != 0) {
      fail("flushing the forward record failed (disk full?)");
      return false;
    }
    unflushed_ = false;
  }
  const std::uint64_t begin = offsets_[i];
  const std::uint64_t end = i + 1 < offsets_.size() ? offsets_[i + 1] : end_;
  buffer_.resize(static_cast<std::size_t>(end - begin));
  const ssize_t got = pread(fileno(file_), buffer_.data(), buffer_.size(), static_cast<off_t>(begin));
  if (got != static_cast<ssize_t>(buffer_.size()) || buffer_.size() < kHeaderBytes) {
    fail("reading the forward record failed");
    return false;
  }
  const auto type_byte = buffer_[0];
  buffer_.erase(buffer_.begin(), buffer_.begin() + kHeaderBytes);
  e.type = static_cast<RecordType>(type_byte);
  In in(buffer_);
  switch (e.type) {
    case RecordType::kIntervalStart:
    case RecordType::kClose:
      e.time_ns = in.get<std::int64_t>();
      e.n = in.get<std::int32_t>();
      {
        const auto flags = in.get<std::uint8_t>();
        e.navigating = (flags & kNodeNavigating) != 0;
        e.inflation_after_outage = (flags & kNodeInflationAfterOutage) != 0;
      }
      e.x = in.state();
      in.symmetric(e.p, e.n);
      break;
    case RecordType::kImu:
      e.x = in.state();
      e.time_ns = e.x.time_ns;
      e.rate_b_rps = in.vec();
      e.force_b_mps2 = in.vec();
      e.gravity_ned_mps2 = in.vec();
      e.mode = static_cast<NavMode>(in.get<std::uint8_t>());
      e.gnss_fix = static_cast<GnssFixType>(in.get<std::uint8_t>());
      e.valid = in.get<std::uint32_t>();
      e.status_flags = in.get<std::uint32_t>();
      break;
    case RecordType::kPropagation:
      e.time_ns = in.get<std::int64_t>();
      e.n = in.get<std::int32_t>();
      e.x = in.state();
      in.symmetric(e.p, e.n);
      e.phi.setIdentity();
      for (int r = 0; r < sx::kDynamicCount; ++r) {
        for (int c = 0; c < e.n; ++c) e.phi(r, c) = in.get<double>();
      }
      break;
    case RecordType::kUpdate: {
      e.time_ns = in.get<std::int64_t>();
      e.n = in.get<std::int32_t>();
      const int rows = in.get<std::int32_t>();
      e.x_before = in.state();
      e.x = in.state();
      e.obs.resize(rows);
      for (int r = 0; r < rows; ++r) {
        e.obs.residual(r) = in.get<double>();
        for (int c = 0; c < e.n; ++c) e.obs.h(r, c) = in.get<double>();
        for (int c = 0; c < rows; ++c) e.obs.r(r, c) = in.get<double>();
      }
      e.dx.setZero();
      for (int c = 0; c < e.n; ++c) e.dx(c) = in.get<double>();
      e.nis = in.get<double>();
      break;
    }
    case RecordType::kRestart:
    case RecordType::kBreak:
      e.time_ns = in.get<std::int64_t>();
      break;
  }
  if (in.short_read()) {
    fail("forward record " + std::to_string(i) + " is shorter than its type needs");
    return false;
  }
  return true;
}

void record_step_start(FilterCore& c) {
  Out out(scratch);
  if (c.step.dt_s == 0.0) {
    put_node(out, c, c.ekf.p);
    emit(c, RecordType::kIntervalStart);
    return;
  }
  if (same_state(c.x, c.record.after_strapdown)) return;
  out.put(c.x.time_ns);
  emit(c, RecordType::kBreak);
}

void record_imu(FilterCore& c, const FilterOptions& o) {
  c.record.after_strapdown = c.x;
  // The forward solution's words (mode, fix in use, validity, status), as replay reports them.
  SolutionInputs in;
  capture_solution(c, o, rot::dcm_from_rpy(o.mounting_rpy_rad), TimeSource::kUnknown, in);
  NavSolution s;
  fill_nav_solution(in, s);
  Out out(scratch);
  out.put(c.x);
  out.put(c.rate_b_rps);
  out.put(c.force_b_mps2);
  out.put(c.earth.gravity_ned_mps2);
  out.put(static_cast<std::uint8_t>(s.mode));
  out.put(static_cast<std::uint8_t>(s.gnss_fix));
  out.put(s.header.valid);
  out.put(s.status_flags);
  emit(c, RecordType::kImu);
}

void record_propagation(FilterCore& c) {
  // Phi = I + G + G^2 / 2 with G = F T, the series discrete_step() applies to P (process_model.cpp).
  // G is zero below row R = sx::kDynamicCount, so G^2 = G.leftCols(R) * G there too.
  constexpr int R = sx::kDynamicCount;
  const SystemRows g = system_matrix(c.x, c.earth, c.step).dense() * c.step.dt_s;
  SystemRows phi_rows = g + 0.5 * g.leftCols<R>() * g;
  phi_rows.leftCols<R>() += Eigen::Matrix<double, R, R>::Identity();
  Out out(scratch);
  put_prior(out, c, phi_rows);
  emit(c, RecordType::kPropagation);
}

void record_covariance_change(FilterCore& c, const Covariance& before, const SystemRows& phi_rows,
                              bool after_outage) {
  Out start(scratch);
  put_node(start, c, before, after_outage);
  emit(c, RecordType::kIntervalStart);
  Out prior(scratch);
  put_prior(prior, c, phi_rows);
  emit(c, RecordType::kPropagation);
}

void record_update(FilterCore& c, const NavState& before, const Observation& obs, const UpdateResult& r) {
  Out out(scratch);
  out.put(c.x.time_ns);
  out.put(static_cast<std::int32_t>(c.ekf.n));
  out.put(static_cast<std::int32_t>(obs.rows()));
  out.put(before);
  out.put(c.x);
  for (int row = 0; row < obs.rows(); ++row) {
    out.put(obs.residual(row));
    for (int col = 0; col < c.ekf.n; ++col) out.put(obs.h(row, col));
    for (int col = 0; col < obs.rows(); ++col) out.put(obs.r(row, col));
  }
  for (int col = 0; col < c.ekf.n; ++col) out.put(r.dx(col));
  out.put(r.nis);
  emit(c, RecordType::kUpdate);
}

void record_restart(FilterCore& c) {
  Out out(scratch);
  out.put(c.x.time_ns);
  emit(c, RecordType::kRestart);
}

}  // namespace navfuse::filter
