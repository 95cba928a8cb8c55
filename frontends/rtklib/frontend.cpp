#include "frontends/rtklib/frontend.hpp"

#include "frontends/rtklib/decoder.hpp"
#include "frontends/rtklib/to_core.hpp"

namespace navfuse::frontends {
namespace {

std::size_t probe(std::span<const std::uint8_t> head) {
  LineFramer framer(rtklib::kMaxLineBytes);
  rtklib::PosLayout layout = rtklib::default_layout(rtklib::Coordinates::kLlhDeg);
  std::size_t found = 0;
  framer.feed(head, [&](std::string_view line) {
    if (!line.empty() && line.front() == '%') {
      found += rtklib::read_header_line(line, layout) ? 1 : 0;
    } else if (rtklib::parse_record(line, layout)) {
      ++found;
    }
  });
  return found;
}

std::unique_ptr<StreamDecoder> make_decoder() { return std::make_unique<rtklib::PosDecoder>(); }

}  // namespace

const FrontendInfo& rtklib::frontend() {
  static const FrontendInfo info{
      .format = "rtklib",
      .description = "RTKLIB solution (.pos): GPST/UTC, lat/lon/height or ECEF, Q, std devs, velocity",
      .probe = &probe,
      .make_decoder = &make_decoder,
      .make_encoder = nullptr,
      .default_profile = config::DeviceProfile::kGeneric,
      .setup_commands = nullptr,  // a file format, not a device
      .find_refusal = nullptr,
      .device_errors = {},
      .odometry_input = false,
      .make_decoder_in_week = nullptr,
  };
  return info;
}

}  // namespace navfuse::frontends
