// Device set-up commands as the apps send them (`navfuse run --configure-device`), and the small
// text helpers the ASCII protocols share to build them and to find a refusal in a reply.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace navfuse::frontends {

// One command as bytes on the wire.
using DeviceCommand = std::vector<std::uint8_t>;

// ASCII command sentences (already checksummed and terminated) as wire commands.
inline std::vector<DeviceCommand> commands_from_sentences(const std::vector<std::string>& sentences) {
  std::vector<DeviceCommand> out;
  out.reserve(sentences.size());
  for (const std::string& s : sentences) out.emplace_back(s.begin(), s.end());
  return out;
}

// The line of a device's reply starting at the first occurrence of `marker` (e.g. "$VNERR"),
// without its line end; "" when `marker` does not occur.
inline std::string line_starting_with(std::span<const std::uint8_t> reply_bytes, std::string_view marker) {
  const std::string_view text(reinterpret_cast<const char*>(reply_bytes.data()), reply_bytes.size());
  const auto at = text.find(marker);
  if (at == std::string_view::npos) return {};
  const auto end = text.find_first_of("\r\n", at);
  return std::string(text.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
}

}  // namespace navfuse::frontends
