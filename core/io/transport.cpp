// open_transport(): the URI (uri.hpp) decides which transport is built and with what options.
#include "core/io/transport.hpp"

#include "core/io/file_transport.hpp"
#include "core/io/serial_port.hpp"
#include "core/io/tcp_client.hpp"
#include "core/io/tcp_listener.hpp"
#include "core/io/udp_socket.hpp"
#include "core/io/uri.hpp"

namespace navfuse::io {

std::unique_ptr<Transport> open_transport(const Uri& uri, Direction direction) {
  switch (uri.scheme) {
    case Scheme::kSerial: {
      SerialOptions o;
      o.path = uri.path;
      o.baud = uri.option("baud", o.baud);
      o.reconnect_ms = static_cast<int>(uri.option("reconnect_ms", o.reconnect_ms));
      o.max_reconnect_ms = static_cast<int>(uri.option("max_reconnect_ms", o.max_reconnect_ms));
      o.queue_bytes = static_cast<std::size_t>(uri.option("queue_bytes", static_cast<long>(o.queue_bytes)));
      return std::make_unique<SerialPort>(std::move(o));
    }
    case Scheme::kTcp: {
      TcpClientOptions o;
      o.host = uri.host;
      o.port = uri.port;
      o.connect_timeout_ms = static_cast<int>(uri.option("connect_timeout_ms", o.connect_timeout_ms));
      o.reconnect_ms = static_cast<int>(uri.option("reconnect_ms", o.reconnect_ms));
      o.max_reconnect_ms = static_cast<int>(uri.option("max_reconnect_ms", o.max_reconnect_ms));
      o.queue_bytes = static_cast<std::size_t>(uri.option("queue_bytes", static_cast<long>(o.queue_bytes)));
      return std::make_unique<TcpClient>(std::move(o));
    }
    case Scheme::kTcpListen: {
      TcpListenerOptions o;
      o.host = uri.host;
      o.port = uri.port;
      o.max_clients = static_cast<std::size_t>(uri.option("max_clients", static_cast<long>(o.max_clients)));
      o.queue_bytes = static_cast<std::size_t>(uri.option("queue_bytes", static_cast<long>(o.queue_bytes)));
      return std::make_unique<TcpListener>(std::move(o));
    }
    case Scheme::kUdp:
    case Scheme::kUdpListen:
      return std::make_unique<UdpSocket>(
          UdpOptions{uri.host, uri.port, uri.scheme == Scheme::kUdpListen});
    case Scheme::kFile:
      return std::make_unique<FileTransport>(uri.path, direction);
  }
  throw TransportError(uri.text + ": unsupported scheme");
}

std::unique_ptr<Transport> open_transport(std::string_view uri, Direction direction) {
  return open_transport(parse_uri(uri), direction);
}

}  // namespace navfuse::io
