// rtklib StreamDecoder (format "rtklib"): RTKLIB solution (.pos) files as GNSS input.
// '%' lines are read for the file's form (pos_layout.hpp) and counted as unknown frames; every
// other non-blank line is a solution (to_core.hpp): a frame when it reads, a bad frame when not.
#pragma once

#include "frontends/common/line_framer.hpp"
#include "frontends/common/stream_decoder.hpp"
#include "frontends/rtklib/pos_layout.hpp"

namespace navfuse::frontends::rtklib {

// RTKLIB's longest solution line (ECEF with velocity, dms...) is about 300 characters.
inline constexpr std::size_t kMaxLineBytes = 2048;

class PosDecoder final : public StreamDecoder {
 public:
  std::string_view format() const override { return "rtklib"; }
  void feed(std::span<const std::uint8_t> bytes, DecodeSink& sink) override;
  void finish(DecodeSink& sink) override;
  const StreamCounters& counters() const override { return framer_.counters(); }
  const PosLayout& layout() const { return layout_; }

 private:
  void on_line(std::string_view line, DecodeSink& sink);

  LineFramer framer_{kMaxLineBytes};
  PosLayout layout_ = default_layout(Coordinates::kLlhDeg);
};

}  // namespace navfuse::frontends::rtklib
