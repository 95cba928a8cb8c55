#include "apps/run/device_setup.hpp"

#include <cstdio>

#include "frontends/mip/commands.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/unicore/commands.hpp"
#include "frontends/vectornav/commands.hpp"

namespace navfuse::apps {
namespace {

std::vector<DeviceCommand> from_sentences(const std::vector<std::string>& sentences) {
  std::vector<DeviceCommand> out;
  out.reserve(sentences.size());
  for (const std::string& s : sentences) out.emplace_back(s.begin(), s.end());
  return out;
}

// The line starting at the first occurrence of `marker`, without its line end.
std::string line_at(std::string_view text, std::string_view marker) {
  const auto at = text.find(marker);
  if (at == std::string_view::npos) return {};
  const auto end = text.find_first_of("\r\n", at);
  return std::string(text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
}

std::string mip_refusal(std::span<const std::uint8_t> bytes) {
  namespace mip = frontends::mip;
  mip::Framer framer;
  std::string refusal;
  std::vector<mip::ReplyEntry> entries;
  framer.feed(bytes, [&](const mip::PacketView& p) {
    if (!refusal.empty() || !mip::set::is_command(p.desc_set)) return;
    entries.clear();
    if (!mip::parse_reply(p.payload, entries)) return;
    for (const auto& e : entries) {
      if (e.code != mip::ReplyCode::kAck) {
        char text[64];
        std::snprintf(text, sizeof text, "MIP NACK %u for command (0x%02X,0x%02X)",
                      static_cast<unsigned>(e.code), p.desc_set, e.cmd_desc);
        refusal = text;
        return;
      }
    }
  });
  return refusal;
}

}  // namespace

std::vector<DeviceCommand> device_setup_commands(std::string_view format) {
  if (format == "vn") return from_sentences(frontends::vectornav::cmd::fusion_setup_commands({}));
  if (format == "unicore") return from_sentences(frontends::unicore::fusion_setup_commands());
  if (format == "mip") return frontends::mip::cv7_setup_sequence();
  return {};
}

std::string find_refusal(std::string_view format, std::span<const std::uint8_t> reply_bytes) {
  if (format == "mip") return mip_refusal(reply_bytes);
  const std::string_view text(reinterpret_cast<const char*>(reply_bytes.data()), reply_bytes.size());
  if (format == "vn") return line_at(text, "$VNERR");
  if (format == "unicore") return line_at(text, "$FAIL");
  return {};
}

}  // namespace navfuse::apps
