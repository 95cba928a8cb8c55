// URI parsing for transports (forms and options documented in uri.hpp).
#include "core/io/uri.hpp"

#include <algorithm>
#include <charconv>
#include <vector>

#include "core/io/serial_port.hpp"

namespace navfuse::io {
namespace {

struct SchemeSpec {
  Scheme scheme;
  std::string_view prefix;  // what the text starts with
  std::string_view form;    // shown in errors
};

// Longest prefixes first, so "tcp-listen://" is not read as "tcp" + garbage.
constexpr SchemeSpec kSchemes[] = {
    {Scheme::kTcpListen, "tcp-listen://", "tcp-listen://[HOST]:PORT"},
    {Scheme::kUdpListen, "udp-listen://", "udp-listen://[HOST]:PORT"},
    {Scheme::kTcp, "tcp://", "tcp://HOST:PORT"},
    {Scheme::kUdp, "udp://", "udp://HOST:PORT or udp://:PORT"},
    {Scheme::kSerial, "serial:", "serial:PATH?baud=N"},
    {Scheme::kFile, "file:", "file:PATH"},
};

struct OptionSpec {
  Scheme scheme;
  std::string_view name;
  long min;
  long max;
};

constexpr OptionSpec kOptions[] = {
    {Scheme::kSerial, "baud", 1, 4000000},  // further restricted to kStandardBaudRates
    {Scheme::kSerial, "reconnect_ms", 1, 3600000},
    {Scheme::kSerial, "max_reconnect_ms", 1, 3600000},
    {Scheme::kSerial, "queue_bytes", 0, 64L << 20},
    {Scheme::kTcp, "connect_timeout_ms", 1, 600000},
    {Scheme::kTcp, "reconnect_ms", 1, 3600000},
    {Scheme::kTcp, "max_reconnect_ms", 1, 3600000},
    {Scheme::kTcp, "queue_bytes", 0, 64L << 20},
    {Scheme::kTcpListen, "max_clients", 1, 1024},
    {Scheme::kTcpListen, "queue_bytes", 0, 64L << 20},
};

class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  Uri parse() {
    Uri uri;
    uri.text = std::string(text_);
    std::string_view rest = text_;
    const SchemeSpec* spec = nullptr;
    for (const SchemeSpec& s : kSchemes) {
      if (rest.starts_with(s.prefix)) {
        spec = &s;
        break;
      }
    }
    if (spec == nullptr) {
      const std::size_t colon = rest.find(':');
      if (colon == std::string_view::npos || colon == 0) {
        fail("missing scheme (expected serial:, file:, tcp://, tcp-listen://, udp://, udp-listen://)");
      }
      fail("unknown scheme '" + std::string(rest.substr(0, colon)) +
           "' (expected serial:, file:, tcp://, tcp-listen://, udp://, udp-listen://)");
    }
    uri.scheme = spec->scheme;
    form_ = spec->form;
    rest.remove_prefix(spec->prefix.size());

    const std::size_t question = rest.find('?');
    if (question != std::string_view::npos) {
      parse_options(rest.substr(question + 1), uri);
      rest = rest.substr(0, question);
    }

    if (uri.scheme == Scheme::kSerial || uri.scheme == Scheme::kFile) {
      if (rest.starts_with("///")) rest.remove_prefix(2);  // serial:///dev/x, file:///tmp/x
      if (rest.empty()) fail("missing path");
      uri.path = std::string(rest);
      return uri;
    }
    parse_authority(rest, uri);
    return uri;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw UriError("bad URI \"" + std::string(text_) + "\": " + why);
  }

  void parse_authority(std::string_view rest, Uri& uri) {
    const bool listen = uri.scheme == Scheme::kTcpListen || uri.scheme == Scheme::kUdpListen;
    std::string_view host;
    std::string_view port_text;
    if (rest.starts_with('[')) {
      const std::size_t close = rest.find(']');
      if (close == std::string_view::npos) fail("unterminated '[' in IPv6 address");
      host = rest.substr(1, close - 1);
      rest.remove_prefix(close + 1);
      if (!rest.starts_with(':')) fail("missing ':PORT' (expected " + std::string(form_) + ")");
      port_text = rest.substr(1);
    } else {
      const std::size_t colon = rest.rfind(':');
      if (colon == std::string_view::npos) fail("missing ':PORT' (expected " + std::string(form_) + ")");
      host = rest.substr(0, colon);
      port_text = rest.substr(colon + 1);
      if (host.find(':') != std::string_view::npos) fail("put an IPv6 address in brackets, e.g. [::1]:PORT");
    }
    if (host.find('/') != std::string_view::npos || port_text.find('/') != std::string_view::npos) {
      fail("unexpected '/' (expected " + std::string(form_) + ")");
    }
    long port = 0;
    if (!to_long(port_text, port) || port < 0 || port > 65535) {
      fail("bad port '" + std::string(port_text) + "' (expected 0-65535)");
    }
    uri.host = std::string(host);
    uri.port = static_cast<std::uint16_t>(port);

    if (uri.scheme == Scheme::kUdp && host.empty()) uri.scheme = Scheme::kUdpListen;  // udp://:PORT
    if (uri.scheme == Scheme::kTcp && host.empty()) {
      fail("missing HOST (use tcp-listen://:PORT to accept connections)");
    }
    if (!listen && uri.scheme != Scheme::kUdpListen && port == 0) fail("port 0 is only for listening");
  }

  void parse_options(std::string_view query, Uri& uri) {
    while (!query.empty()) {
      const std::size_t amp = query.find('&');
      const std::string_view item = query.substr(0, amp);
      query = amp == std::string_view::npos ? std::string_view() : query.substr(amp + 1);
      const std::size_t eq = item.find('=');
      const std::string_view name = item.substr(0, eq);
      const OptionSpec* spec = nullptr;
      std::string known;
      for (const OptionSpec& o : kOptions) {
        if (o.scheme != uri.scheme) continue;
        if (o.name == name) spec = &o;
        known += (known.empty() ? "" : ", ") + std::string(o.name);
      }
      if (spec == nullptr) {
        fail("unknown option '" + std::string(name) + "' for " + std::string(to_string(uri.scheme)) +
             (known.empty() ? " (it takes none)" : " (known: " + known + ")"));
      }
      long value = 0;
      if (eq == std::string_view::npos || !to_long(item.substr(eq + 1), value)) {
        fail("option '" + std::string(name) + "' needs an integer value");
      }
      if (value < spec->min || value > spec->max) {
        fail("option '" + std::string(name) + "' out of range [" + std::to_string(spec->min) +
             ", " + std::to_string(spec->max) + "]");
      }
      if (name == "baud" && !is_standard_baud_rate(value)) {
        fail("unsupported baud rate " + std::to_string(value) + " (termios(3) standard rates only)");
      }
      if (!uri.options.emplace(std::string(name), value).second) {
        fail("option '" + std::string(name) + "' given twice");
      }
    }
  }

  static bool to_long(std::string_view text, long& value) {
    if (text.empty()) return false;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size();
  }

  std::string_view text_;
  std::string_view form_;
};

}  // namespace

std::string_view to_string(Scheme scheme) {
  switch (scheme) {
    case Scheme::kSerial: return "serial";
    case Scheme::kTcp: return "tcp";
    case Scheme::kTcpListen: return "tcp-listen";
    case Scheme::kUdp: return "udp";
    case Scheme::kUdpListen: return "udp-listen";
    case Scheme::kFile: return "file";
  }
  return "?";
}

Uri parse_uri(std::string_view text) { return Parser(text).parse(); }

}  // namespace navfuse::io
