// TCP client transport: connects without blocking (connect(2) on a non-blocking socket, then
// poll(2) for writability, POSIX connect(2) "EINPROGRESS"), and reconnects with exponential
// backoff whenever the connection fails or the peer goes away.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/io/reconnect_backoff.hpp"
#include "core/io/socket_address.hpp"
#include "core/io/transport.hpp"
#include "core/io/unique_fd.hpp"
#include "core/io/write_queue.hpp"

namespace navfuse::io {

struct TcpClientOptions {
  std::string host;              // name or address; resolved once, at construction
  std::uint16_t port = 0;
  int connect_timeout_ms = 2000; // an attempt not complete by then is abandoned and retried
  int reconnect_ms = 250;        // first retry delay; doubles per failure up to the cap
  int max_reconnect_ms = 5000;
  std::size_t queue_bytes = 65536;  // output held while the socket buffer is full
};

class TcpClient : public Transport {
 public:
  // Starts the first connection attempt and returns without waiting for it. Throws
  // TransportError only if the host does not resolve.
  explicit TcpClient(TcpClientOptions options);

  std::ptrdiff_t read(std::span<std::uint8_t> buffer, int timeout_ms) override;
  // While not connected, data is dropped (counted in bytes_dropped), not held for later:
  // navigation output is stale by the time a link comes back.
  std::ptrdiff_t write(std::span<const std::uint8_t> data) override;
  bool is_open() const override { return state_ == State::kConnected; }
  bool reopen() override;
  bool wait_open(int timeout_ms) override;
  std::string describe() const override;

 private:
  enum class State { kIdle, kConnecting, kConnected };

  void start_connect();
  // Advances a pending connect, waiting at most wait_ms. Returns true once connected.
  bool progress(int wait_ms);
  void failed(const std::string& why);  // closes and schedules the next attempt
  void connected();
  std::string uri_text() const;  // "tcp://HOST:PORT"

  TcpClientOptions options_;
  std::vector<SocketAddress> addresses_;
  std::size_t next_address_ = 0;  // rotate through every resolved address
  UniqueFd fd_;
  State state_ = State::kIdle;
  Deadline connect_deadline_{0};
  WriteQueue queue_;
  ReconnectBackoff backoff_;
  bool ever_connected_ = false;
};

}  // namespace navfuse::io
