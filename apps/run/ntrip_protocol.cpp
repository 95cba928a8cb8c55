#include "apps/run/ntrip_protocol.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {
namespace {

constexpr std::uint16_t kNtripDefaultPort = 2101;  // IANA's port for NTRIP
constexpr std::size_t kMaxHeaderBytes = 16384;     // a caster's answer header is a few lines

std::string base64(std::string_view in) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, in.size() - i);
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 3; ++k) v = (v << 8) | (k < n ? static_cast<std::uint8_t>(in[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kAlphabet[(v >> (18 - 6 * k)) & 0x3F] : '=';
  }
  return out;
}

std::uint16_t parse_port(std::string_view text, const std::string& argument) {
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value == 0 || value > 65535) {
    throw CommandError("--corrections '" + argument + "': bad port '" + std::string(text) + "'");
  }
  return static_cast<std::uint16_t>(value);
}

[[noreturn]] void bad_option(std::string_view option, const std::string& argument, const std::string& why) {
  throw CommandError("--corrections '" + argument + "': option '" + std::string(option) + "': " + why);
}

// The query after '?': options joined by '&' (version=1|2 for NTRIP; gga=SECONDS for both).
void parse_options(std::string_view query, const std::string& argument, CorrectionsSource& s) {
  while (!query.empty()) {
    const auto amp = query.find('&');
    const std::string_view option = query.substr(0, amp);
    query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
    const auto eq = option.find('=');
    const std::string_view key = option.substr(0, eq);
    const std::string_view value = eq == std::string_view::npos ? std::string_view{} : option.substr(eq + 1);
    if (key == "version" && s.ntrip) {
      if (value != "1" && value != "2") bad_option(option, argument, "version=1 or version=2");
      s.version = value == "1" ? 1 : 2;
    } else if (key == "gga") {
      double seconds = -1.0;
      const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), seconds);
      if (ec != std::errc() || end != value.data() + value.size() || !(seconds >= 0.0) || !std::isfinite(seconds)) {
        bad_option(option, argument, "seconds between GGA uploads, >= 0 (0: none)");
      }
      s.gga_interval_s = seconds;
    } else {
      bad_option(option, argument, s.ntrip ? "unknown (version=1|2, gga=SECONDS)" : "unknown (gga=SECONDS)");
    }
  }
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// The source as messages and the run summary show it: the password replaced by "***".
std::string without_password(const std::string& argument) {
  if (!argument.starts_with("ntrip://")) return argument;
  const std::string_view rest = std::string_view(argument).substr(8, argument.find('?') - 8);
  const auto at = rest.rfind('@');
  const auto colon = at == std::string_view::npos ? at : rest.substr(0, at).find(':');
  if (colon == std::string_view::npos) return argument;
  std::string shown = argument;
  shown.replace(8 + colon + 1, at - colon - 1, "***");
  return shown;
}

std::string_view trim_line_end(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.remove_suffix(1);
  return line;
}

}  // namespace

CorrectionsSource parse_corrections_source(const std::string& argument) {
  CorrectionsSource s;
  s.text = without_password(argument);  // what every message below shows
  const std::string& shown = s.text;
  std::string_view rest = argument;
  if (rest.starts_with("ntrip://")) {
    s.ntrip = true;
    rest.remove_prefix(8);
  } else if (rest.starts_with("tcp://")) {
    rest.remove_prefix(6);
  } else {
    throw CommandError("--corrections '" + shown + "': expected " + std::string(kCorrectionsSourceForms));
  }
  if (const auto q = rest.find('?'); q != std::string_view::npos) {
    parse_options(rest.substr(q + 1), shown, s);
    rest = rest.substr(0, q);
  }
  if (s.ntrip) {
    if (const auto at = rest.rfind('@'); at != std::string_view::npos) {
      const std::string_view credentials = rest.substr(0, at);
      const auto colon = credentials.find(':');
      s.user = std::string(credentials.substr(0, colon));
      if (colon != std::string_view::npos) s.password = std::string(credentials.substr(colon + 1));
      rest.remove_prefix(at + 1);
    }
    const auto slash = rest.find('/');
    if (slash == std::string_view::npos || slash + 1 == rest.size()) {
      throw CommandError("--corrections '" + shown + "': no mountpoint (ntrip://HOST[:PORT]/MOUNT)");
    }
    s.mount = std::string(rest.substr(slash + 1));
    rest = rest.substr(0, slash);
  }
  const auto colon = rest.rfind(':');
  s.host = std::string(rest.substr(0, colon));
  if (colon != std::string_view::npos) {
    s.port = parse_port(rest.substr(colon + 1), shown);
  } else if (s.ntrip) {
    s.port = kNtripDefaultPort;
  } else {
    throw CommandError("--corrections '" + shown + "': tcp:// needs HOST:PORT");
  }
  if (s.host.empty()) throw CommandError("--corrections '" + shown + "': no host");
  return s;
}

std::string ntrip_request(const CorrectionsSource& source, std::string_view gga) {
  std::string r = "GET /" + source.mount + (source.version == 1 ? " HTTP/1.0\r\n" : " HTTP/1.1\r\n");
  if (source.version == 2) {
    r += "Host: " + source.host + ":" + std::to_string(source.port) + "\r\n";
    r += "Ntrip-Version: Ntrip/2.0\r\n";
  }
  r += "User-Agent: NTRIP navfuse/0.1\r\n";
  if (!source.user.empty()) r += "Authorization: Basic " + base64(source.user + ":" + source.password) + "\r\n";
  // NTRIP 2.0 carries the rover's position in a header of its own, the sentence without its
  // line end; NTRIP 1.0 has none, and its casters read the sentence after the request.
  if (source.version == 2 && !gga.empty()) r += "Ntrip-GGA: " + std::string(trim_line_end(gga)) + "\r\n";
  if (source.version == 2) r += "Connection: close\r\n";
  r += "\r\n";
  if (source.version == 1) r += gga;
  return r;
}

std::optional<NtripAnswer> parse_ntrip_answer(std::string_view head, const std::string& mount) {
  NtripAnswer a;
  const auto line_end = head.find("\r\n");
  if (line_end == std::string_view::npos) {
    if (head.size() > kMaxHeaderBytes) return NtripAnswer{.ok = false, .chunked = false, .header_bytes = 0, .reason = "no answer line"};
    return std::nullopt;
  }
  const std::string_view status = head.substr(0, line_end);
  // NTRIP 1.0 casters answer "ICY 200 OK" and the data follows that line at once.
  if (status.starts_with("ICY 200")) {
    a.ok = true;
    a.header_bytes = line_end + 2;
    return a;
  }
  if (status.starts_with("SOURCETABLE")) {
    a.reason = "the caster has no mountpoint '" + mount + "' (it answered with its source table)";
    return a;
  }
  const auto end = head.find("\r\n\r\n");
  if (end == std::string_view::npos) {
    if (head.size() > kMaxHeaderBytes) return NtripAnswer{.ok = false, .chunked = false, .header_bytes = 0, .reason = "answer header too long"};
    return std::nullopt;
  }
  a.header_bytes = end + 4;
  const bool http = status.starts_with("HTTP/1.");
  const auto space = status.find(' ');
  const std::string_view code = space == std::string_view::npos ? std::string_view{} : status.substr(space + 1, 3);
  if (!http || code != "200") {
    a.reason = "the caster answered '" + std::string(status) + "'" +
               (code == "401" ? " (user or password wrong)" : code == "404" ? " (no such mountpoint)" : "");
    return a;
  }
  const std::string headers = lower(head.substr(line_end + 2, end - line_end - 2));
  if (headers.find("content-type: gnss/sourcetable") != std::string::npos) {
    a.reason = "the caster has no mountpoint '" + mount + "' (it answered with its source table)";
    return a;
  }
  a.ok = true;
  a.chunked = headers.find("transfer-encoding: chunked") != std::string::npos;
  return a;
}

bool ChunkedDecoder::feed(std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& out) {
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const char c = static_cast<char>(bytes[i]);
    switch (state_) {
      case State::kSize: {
        const int digit = (c >= '0' && c <= '9') ? c - '0' : (c >= 'a' && c <= 'f') ? c - 'a' + 10
                        : (c >= 'A' && c <= 'F') ? c - 'A' + 10 : -1;
        if (digit >= 0 && size_digits_ < 15) {
          remaining_ = remaining_ * 16 + static_cast<std::uint64_t>(digit);
          ++size_digits_;
        } else if (size_digits_ > 0 && (c == ';' || c == ' ' || c == '\t')) {
          state_ = State::kSizeExtension;
        } else if (size_digits_ > 0 && c == '\r') {
          state_ = State::kSizeLf;
        } else {
          state_ = State::kFailed;
        }
        break;
      }
      case State::kSizeExtension:
        if (c == '\r') state_ = State::kSizeLf;
        break;
      case State::kSizeLf:
        if (c != '\n') {
          state_ = State::kFailed;
        } else {
          state_ = remaining_ == 0 ? State::kEnded : State::kData;
        }
        break;
      case State::kData: {
        const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(remaining_, bytes.size() - i));
        out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(i),
                   bytes.begin() + static_cast<std::ptrdiff_t>(i + n));
        remaining_ -= n;
        i += n - 1;
        if (remaining_ == 0) state_ = State::kDataCr;
        break;
      }
      case State::kDataCr: state_ = c == '\r' ? State::kDataLf : State::kFailed; break;
      case State::kDataLf:
        if (c == '\n') {
          state_ = State::kSize;
          size_digits_ = 0;
        } else {
          state_ = State::kFailed;
        }
        break;
      case State::kEnded: return true;  // trailers after the last chunk: nothing more to give
      case State::kFailed: return false;
    }
  }
  return state_ != State::kFailed;
}

}  // namespace navfuse::apps
