// Transport URIs (DESIGN.md "Command line", contract forms first):
//
//   serial:PATH[?baud=N]          serial device, e.g. serial:/dev/ttyUSB0?baud=921600
//                                 (serial:///dev/ttyUSB0 is accepted too)
//   tcp://HOST:PORT               TCP client; reconnects when the peer goes away
//   tcp-listen://[HOST]:PORT      TCP server; HOST omitted = all interfaces; PORT 0 = ephemeral
//   udp://HOST:PORT               UDP: send datagrams to HOST:PORT (replies are readable)
//   udp://:PORT                   UDP: bind PORT on all interfaces and receive (same as below)
//   udp-listen://[HOST]:PORT      UDP: bind HOST:PORT and receive; write() answers the last sender
//   file:PATH                     file: read for inputs; create/truncate for outputs;
//                                 file:- is stdin (input) or stdout (output)
//
// HOST is a name, an IPv4 address or a bracketed IPv6 address ([::1]). Options follow `?` as
// `name=integer` pairs joined by `&`; each scheme accepts only its own:
//   serial:      baud (default 115200; one of kStandardBaudRates in serial_port.hpp),
//                reconnect_ms (first retry delay after the device disappears, default 500),
//                max_reconnect_ms (backoff cap, default 5000), queue_bytes (output queue, 65536)
//   tcp:         connect_timeout_ms (default 2000), reconnect_ms (default 250),
//                max_reconnect_ms (default 5000), queue_bytes (default 65536)
//   tcp-listen:  max_clients (default 16), queue_bytes (per client, default 262144: a client
//                whose backlog would exceed it is disconnected and counted in clients_dropped)
// Paths cannot contain `?`. A bad URI throws UriError whose what() is one line, e.g.
//   bad URI "tcp://localhost": missing ':PORT' (expected tcp://HOST:PORT)
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "core/io/transport.hpp"

namespace navfuse::io {

enum class Scheme { kSerial, kTcp, kTcpListen, kUdp, kUdpListen, kFile };
std::string_view to_string(Scheme scheme);  // "serial", "tcp", "tcp-listen", ...

class UriError : public TransportError {
 public:
  using TransportError::TransportError;
};

struct Uri {
  Scheme scheme = Scheme::kFile;
  std::string text;         // as given
  std::string path;         // serial device or file path
  std::string host;         // tcp/udp; "" = all interfaces (listen forms only)
  std::uint16_t port = 0;   // tcp/udp; 0 = ephemeral (listen forms only)
  std::map<std::string, long, std::less<>> options;  // validated: known names, in range

  // The option's value, or `fallback` when the URI does not set it.
  long option(std::string_view name, long fallback) const {
    const auto it = options.find(name);
    return it == options.end() ? fallback : it->second;
  }
};

Uri parse_uri(std::string_view text);

}  // namespace navfuse::io
