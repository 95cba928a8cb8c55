// The UM220-INS's answers to commands (spec L250-L282; digest §1.1, §3.3): "$OK", "$FAIL,code",
// the command echo "#<command>" (fw >= R3.4.0.0, L250-L260), and configuration reports — the
// same "$CFGxxx,..." sentence sent back in reply to a query (L160), plus PDTINFO / AIDINFO /
// LSF query answers.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "frontends/nmea/fields.hpp"
#include "frontends/nmea/framer.hpp"

namespace navfuse::frontends::unicore {

enum class ReplyKind : std::uint8_t {
  // "$OK" may come as "$OK", "$OK*04" or "$OK,*28": the spec shows only the first (digest §11
  // item 4); all three parse.
  kOk = 0,      // command accepted ($OK; with AIDTIME/AIDPOS only "format accepted", L655, L674)
  kFail = 1,    // $FAIL,errorCode
  kEcho = 2,    // #<user command>
  kReport = 3,  // $CFGxxx / PDTINFO / AIDINFO reply to a query
};

// FAIL errorCode (L282).
enum class FailCode : std::uint32_t { kIllegalOrBadParameter = 0, kChecksum = 1 };

struct Reply {
  ReplyKind kind = ReplyKind::kOk;
  std::optional<std::uint32_t> fail_code;  // kFail only (absent if the field was empty/malformed)
  nmea::Fields fields;                     // [0] = name without '$'/'#'; views into the frame
};

// Classifies one framed sentence (frame.body / frame.start from SentenceFramer). nullopt if it is
// neither a reply nor a configuration report (e.g. a navigation output).
std::optional<Reply> parse_reply(const nmea::Frame& frame);
// The same for one complete line such as "$OK*04\r\n" or "$FAIL,1": checks the checksum when
// present. Views in the result point into `line`.
std::optional<Reply> parse_reply_line(std::string_view line);

// Whether `name` (case-insensitive, without '$') is a reply or configuration-report name.
bool is_reply_name(std::string_view name);

// Looks through the bytes received after a command for a refusal; returns the first "$FAIL,..."
// line (L282), "" when there is none.
std::string find_refusal(std::span<const std::uint8_t> reply_bytes);

// Feeds a byte stream (the command port) and calls `on_reply` for each reply found; other
// sentences are ignored. Counters as for any framer.
class ReplyReader {
 public:
  explicit ReplyReader(nmea::FramerOptions options = {}) : framer_(options) {}
  void feed(std::span<const std::uint8_t> bytes, const std::function<void(const Reply&)>& on_reply);
  const frontends::StreamCounters& counters() const { return framer_.counters(); }

 private:
  nmea::SentenceFramer framer_;
};

}  // namespace navfuse::frontends::unicore
