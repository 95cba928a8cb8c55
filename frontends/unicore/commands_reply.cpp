#include "frontends/unicore/commands_reply.hpp"

#include "core/bytes/checks.hpp"
#include "frontends/common/device_command.hpp"

namespace navfuse::frontends::unicore {
namespace {

// Headers that come back as configuration reports: every CFG* command (L160) plus the query
// outputs PDTINFO (L213-L231) and AIDINFO (L684-L704).
constexpr std::string_view kReportPrefix = "CFG";
constexpr std::string_view kReportNames[] = {"PDTINFO", "AIDINFO", "RESET"};

bool starts_with_ci(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && nmea::iequals(s.substr(0, prefix.size()), prefix);
}

}  // namespace

bool is_reply_name(std::string_view name) {
  if (nmea::iequals(name, "OK") || nmea::iequals(name, "FAIL")) return true;
  if (starts_with_ci(name, kReportPrefix)) return true;
  for (std::string_view n : kReportNames) {
    if (nmea::iequals(name, n)) return true;
  }
  return false;
}

std::optional<Reply> parse_reply(const nmea::Frame& frame) {
  Reply r;
  if (!r.fields.split(frame.body) || r.fields.name().empty()) return std::nullopt;
  const std::string_view name = r.fields.name();
  if (frame.start == '#') {
    r.kind = ReplyKind::kEcho;
    return r;
  }
  if (nmea::iequals(name, "OK")) {
    r.kind = ReplyKind::kOk;
    return r;
  }
  if (nmea::iequals(name, "FAIL")) {
    r.kind = ReplyKind::kFail;
    r.fail_code = nmea::parse_uint(r.fields[1]);
    return r;
  }
  if (!is_reply_name(name)) return std::nullopt;
  r.kind = ReplyKind::kReport;
  return r;
}

std::optional<Reply> parse_reply_line(std::string_view line) {
  // Frame the line with the same rules as the stream (checksum optional but never wrong). The
  // framer may hand out views into its own carry-over buffer, so only the frame's position is
  // kept and the reply is parsed from `line` itself.
  nmea::SentenceFramer framer;
  std::optional<nmea::Frame> found;
  const auto on_frame = [&](const nmea::Frame& f) {
    if (!found) found = f;
  };
  framer.feed(bytes::as_bytes(line), on_frame);
  // A line given without its terminator is complete by definition.
  if (!found) framer.feed(bytes::as_bytes("\r\n"), on_frame);
  if (!found || found->offset >= line.size()) return std::nullopt;
  nmea::Frame frame = *found;
  frame.body = line.substr(static_cast<std::size_t>(frame.offset) + 1, frame.body.size());
  return parse_reply(frame);
}

void ReplyReader::feed(std::span<const std::uint8_t> bytes,
                       const std::function<void(const Reply&)>& on_reply) {
  framer_.feed(bytes, [&](const nmea::Frame& f) {
    if (const auto r = parse_reply(f)) on_reply(*r);
  });
}

std::string find_refusal(std::span<const std::uint8_t> reply_bytes) { return line_starting_with(reply_bytes, "$FAIL"); }

}  // namespace navfuse::frontends::unicore
