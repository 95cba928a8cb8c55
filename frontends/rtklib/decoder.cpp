#include "frontends/rtklib/decoder.hpp"

#include "frontends/common/text_fields.hpp"
#include "frontends/rtklib/to_core.hpp"

namespace navfuse::frontends::rtklib {

void PosDecoder::feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) {
  framer_.feed(bytes, [&](std::string_view line) { on_line(line, sink); });
}

void PosDecoder::finish(DecodeSink& sink) {
  framer_.finish([&](std::string_view line) { on_line(line, sink); });
}

void PosDecoder::on_line(std::string_view line, DecodeSink& sink) {
  if (text::is_blank_line(line)) {
    framer_.skip_line(/*blank=*/true);
    return;
  }
  if (line.front() == '%') {
    read_header_line(line, layout_);
    framer_.skip_line(/*blank=*/false);
    return;
  }
  const auto record = parse_record(line, layout_);
  if (!record) {
    framer_.reject_line();
    return;
  }
  framer_.accept_line();
  if (sink.wants_frames()) sink.on_frame(to_frame_record(*record, framer_.line_offset()));
  to_core(*record, sink);
}

}  // namespace navfuse::frontends::rtklib
