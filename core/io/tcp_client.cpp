// TCP client transport (tcp_client.hpp).
#include "core/io/tcp_client.hpp"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>

namespace navfuse::io {

TcpClient::TcpClient(TcpClientOptions options)
    : options_(std::move(options)),
      queue_(options_.queue_bytes),
      backoff_(options_.reconnect_ms, options_.max_reconnect_ms) {
  addresses_ = resolve(options_.host, options_.port, SOCK_STREAM, false, uri_text());
  start_connect();
}

void TcpClient::start_connect() {
  const SocketAddress& address = addresses_[next_address_++ % addresses_.size()];
  fd_.reset(::socket(address.family(), SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  if (!fd_) {
    failed(errno_text("socket", errno));
    return;
  }
  if (::connect(fd_.get(), address.get(), address.length) == 0) {
    connected();  // loopback can complete at once
    return;
  }
  if (errno != EINPROGRESS) {
    failed(errno_text("connect " + to_string(address), errno));
    return;
  }
  state_ = State::kConnecting;
  connect_deadline_ = Deadline(options_.connect_timeout_ms);
}

void TcpClient::connected() {
  state_ = State::kConnected;
  // Navigation messages are small and latency matters more than packing: disable Nagle
  // (tcp(7) TCP_NODELAY). Best effort.
  const int one = 1;
  (void)::setsockopt(fd_.get(), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  queue_.clear();
  backoff_.succeeded();
  if (ever_connected_) ++stats_.reconnects;
  ever_connected_ = true;
}

void TcpClient::failed(const std::string& why) {
  record_error(uri_text() + ": " + why);
  fd_.reset();
  queue_.clear();
  state_ = State::kIdle;
  backoff_.failed();
}

bool TcpClient::progress(int wait_ms) {
  if (state_ == State::kIdle && backoff_.due()) start_connect();
  if (state_ != State::kConnecting) return state_ == State::kConnected;
  pollfd p{fd_.get(), POLLOUT, 0};
  const int ready = ::poll(&p, 1, std::min(wait_ms, connect_deadline_.remaining_ms()));
  if (ready < 0 && errno != EINTR) {
    failed(errno_text("poll", errno));
  } else if (ready > 0) {
    // The outcome of a non-blocking connect is in SO_ERROR (POSIX connect(2), socket(7)).
    int err = 0;
    socklen_t len = sizeof err;
    if (::getsockopt(fd_.get(), SOL_SOCKET, SO_ERROR, &err, &len) != 0) err = errno;
    if (err == 0) {
      connected();
    } else {
      failed(errno_text("connect", err));
    }
  } else if (connect_deadline_.expired()) {
    failed("connect: timed out after " + std::to_string(options_.connect_timeout_ms) + " ms");
  }
  return state_ == State::kConnected;
}

bool TcpClient::reopen() {
  fd_.reset();
  state_ = State::kIdle;
  start_connect();
  return is_open();
}

bool TcpClient::wait_open(int timeout_ms) {
  const Deadline deadline(timeout_ms);
  while (!progress(deadline.remaining_ms())) {
    if (deadline.expired()) return false;
    if (state_ == State::kIdle) {
      ::poll(nullptr, 0, std::min(deadline.remaining_ms(), ms_until(backoff_.next_attempt())));
    }
  }
  return true;
}

std::ptrdiff_t TcpClient::read(std::span<std::uint8_t> buffer, int timeout_ms) {
  const Deadline deadline(timeout_ms);
  for (;;) {
    if (!progress(deadline.remaining_ms())) {
      if (deadline.expired()) return 0;
      if (state_ == State::kIdle) {
        ::poll(nullptr, 0, std::min(deadline.remaining_ms(), ms_until(backoff_.next_attempt())));
      }
      continue;
    }
    pollfd p{fd_.get(), static_cast<short>(POLLIN | (queue_.empty() ? 0 : POLLOUT)), 0};
    const int ready = ::poll(&p, 1, deadline.remaining_ms());
    if (ready < 0) {
      if (errno == EINTR) continue;
      failed(errno_text("poll", errno));
      continue;
    }
    if (ready == 0) return 0;
    if ((p.revents & POLLOUT) &&
        queue_.flush(fd_.get(), true, stats_.bytes_written) == WriteQueue::Result::kError) {
      failed(errno_text("send", queue_.error()));
      continue;
    }
    if (p.revents & (POLLIN | POLLHUP | POLLERR)) {
      const ssize_t n = ::recv(fd_.get(), buffer.data(), buffer.size(), MSG_DONTWAIT);
      if (n > 0) {
        stats_.bytes_read += static_cast<std::uint64_t>(n);
        return n;
      }
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) continue;
      failed(n == 0 ? "connection closed by peer" : errno_text("recv", errno));
    }
    if (deadline.expired()) return 0;
  }
}

std::ptrdiff_t TcpClient::write(std::span<const std::uint8_t> data) {
  if (!progress(0)) {
    stats_.bytes_dropped += data.size();
    return 0;
  }
  switch (queue_.write(fd_.get(), true, data, stats_.bytes_written)) {
    case WriteQueue::Result::kOk:
      return static_cast<std::ptrdiff_t>(data.size());
    case WriteQueue::Result::kOverflow:
      stats_.bytes_dropped += data.size();
      record_error(uri_text() + ": output queue full, message dropped");
      return 0;
    case WriteQueue::Result::kError:
      break;
  }
  failed(errno_text("send", queue_.error()));
  stats_.bytes_dropped += data.size();
  return 0;
}

std::string TcpClient::uri_text() const {
  const bool v6 = options_.host.find(':') != std::string::npos;
  return "tcp://" + (v6 ? "[" + options_.host + "]" : options_.host) + ":" +
         std::to_string(options_.port);
}

std::string TcpClient::describe() const {
  const std::string text = uri_text();
  switch (state_) {
    case State::kIdle: return text + " (disconnected)";
    case State::kConnecting: return text + " (connecting)";
    case State::kConnected: return text + " (connected)";
  }
  return text;
}

}  // namespace navfuse::io
