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
  static const FrontendInfo info = file_reader_info(
      "rtklib", "RTKLIB solution (.pos): GPST/UTC, lat/lon/height or ECEF, Q, std devs, velocity", &probe,
      &make_decoder);
  return info;
}

}  // namespace navfuse::frontends
