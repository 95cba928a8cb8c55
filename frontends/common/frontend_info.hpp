// What a front-end registers with the apps (README "Front-end layout"): everything the apps need
// to know per protocol, so that they never compare format names. A difference between protocols
// that an app must act on becomes a field here, filled in the protocol's frontend.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/config/config.hpp"
#include "core/measurements/measurements.hpp"
#include "frontends/common/device_command.hpp"
#include "frontends/common/device_error_class.hpp"
#include "frontends/common/setup_step.hpp"
#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends {

struct FrontendInfo {
  std::string_view format;       // "fe", "mip", "vn", "unicore": the INPUT prefix of DESIGN.md
  std::string_view description;  // one line for --help
  // Confidence that `head` (the first bytes of a stream, up to 64 KiB) is this protocol: the
  // number of complete, checksum-valid frames found in it. 0 = not this protocol.
  std::size_t (*probe)(std::span<const std::uint8_t> head) = nullptr;
  std::unique_ptr<StreamDecoder> (*make_decoder)() = nullptr;
  // nullptr when navfuse cannot write this protocol (then `navfuse sim` does not offer it).
  std::unique_ptr<MeasurementEncoder> (*make_encoder)() = nullptr;

  // The config defaults (core/config device profiles) of a stream in this format, used when no
  // --config is given.
  config::DeviceProfile default_profile = config::DeviceProfile::kGeneric;

  // `navfuse run --configure-device`: the commands that make a fresh device stream what fusion
  // needs and give it the installation geometry of `config` (lever arms, baseline), each write
  // read back and checked; sent when the input link opens. nullptr when the device needs none.
  std::vector<SetupStep> (*setup_steps)(const config::Config& config) = nullptr;
  // Looks through the bytes received after a set-up command for the device's refusal; returns a
  // one-line description of the first one, "" when there is none. nullptr: replies not checked.
  std::string (*find_refusal)(std::span<const std::uint8_t> reply_bytes) = nullptr;

  // `navfuse sim`: the errors of the device's own INS solution written beside the measurements.
  DeviceErrorClass device_errors;
  // `navfuse sim --wheel-out`: this protocol is the one a host uses to send wheel / vehicle speed
  // to a fusion device, so simulated odometry is written in it.
  bool odometry_input = false;
  // `navfuse sim`: what the protocol's IMU increments contain (a VN-300's are coning- and
  // sculling-integrated on board); the decoder stamps the same on every ImuSample it makes.
  ImuIncrements imu_increments = ImuIncrements::kRawIntegrals;
  // Formats whose bytes do not carry the GPS week (imutxt: seconds of week only) are decoded in a
  // week given from outside; nullptr for every format that times itself.
  std::unique_ptr<StreamDecoder> (*make_decoder_in_week)(std::int32_t gps_week) = nullptr;
};

// The registration of a file format that is read, never written and not a device (imutxt,
// rtklib): no encoder, no set-up commands or replies, no device errors, generic config defaults.
constexpr FrontendInfo file_reader_info(std::string_view format, std::string_view description,
                                        std::size_t (*probe)(std::span<const std::uint8_t>),
                                        std::unique_ptr<StreamDecoder> (*make_decoder)(),
                                        std::unique_ptr<StreamDecoder> (*make_decoder_in_week)(std::int32_t) = nullptr) {
  return FrontendInfo{
      .format = format,
      .description = description,
      .probe = probe,
      .make_decoder = make_decoder,
      .make_encoder = nullptr,
      .default_profile = config::DeviceProfile::kGeneric,
      .setup_steps = nullptr,
      .find_refusal = nullptr,
      .device_errors = {},
      .odometry_input = false,
      .make_decoder_in_week = make_decoder_in_week,
  };
}

}  // namespace navfuse::frontends
