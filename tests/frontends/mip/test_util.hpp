// Helpers shared by the MIP tests: hex parsing, collecting sinks, FrameRecord lookups.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/bytes/byte_writer.hpp"
#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends::mip::test {

inline std::vector<std::uint8_t> hex(std::string_view s) {
  std::vector<std::uint8_t> out;
  int nibble = -1;
  for (char c : s) {
    int v;
    if (c >= '0' && c <= '9') v = c - '0';
    else if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F') v = c - 'A' + 10;
    else continue;  // spacing as printed in the doc
    if (nibble < 0) {
      nibble = v;
    } else {
      out.push_back(static_cast<std::uint8_t>(nibble << 4 | v));
      nibble = -1;
    }
  }
  return out;
}

// The head of every 0x13 aiding measurement (digest §5.1): Time{u8 timebase, u8 reserved,
// u64 ns}, then u8 frame id. Timebase 2 = external time (GPS ns), 3 = time of arrival.
inline void aiding_head(bytes::BeWriter& w, std::uint64_t ns, std::uint8_t frame, std::uint8_t timebase = 2) {
  w.u8(timebase);
  w.u8(1);
  w.u64(ns);
  w.u8(frame);
}

// (0x13,0x22) LLH position aiding data: head, lat/lon/height f64, std f32 x3, valid u16.
inline std::vector<std::uint8_t> llh_meas(std::uint64_t ns, std::uint8_t frame, double lat_deg, double lon_deg,
                                          double h, Eigen::Vector3d s, std::uint16_t valid, std::uint8_t timebase = 2) {
  std::vector<std::uint8_t> d;
  bytes::BeWriter w(d);
  aiding_head(w, ns, frame, timebase);
  w.f64(lat_deg);
  w.f64(lon_deg);
  w.f64(h);
  for (int i = 0; i < 3; ++i) w.f32(static_cast<float>(s[i]));
  w.u16(valid);
  return d;
}

struct CollectingSink : DecodeSink {
  bool frames = false;
  std::vector<Measurement> measurements;
  std::vector<FrameRecord> records;
  void on_measurement(const Measurement& m) override { measurements.push_back(m); }
  void on_frame(const FrameRecord& r) override { records.push_back(r); }
  bool wants_frames() const override { return frames; }
  std::size_t count(MeasurementKind k) const {
    std::size_t n = 0;
    for (const auto& m : measurements) n += kind_of(m) == k;
    return n;
  }
};

inline std::optional<double> number(const FieldValue& v) {
  if (const auto* u = std::get_if<std::uint64_t>(&v)) return static_cast<double>(*u);
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&v)) return *d;
  return std::nullopt;
}

// The n-th (0-based) value named `name` in a record.
inline std::optional<double> field(const FrameRecord& r, std::string_view name, int nth = 0) {
  for (const auto& [k, v] : r.fields)
    if (k == name && nth-- == 0) return number(v);
  return std::nullopt;
}

}  // namespace navfuse::frontends::mip::test
