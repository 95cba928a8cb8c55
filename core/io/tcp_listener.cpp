// TCP listener transport (tcp_listener.hpp).
#include "core/io/tcp_listener.hpp"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>

#include <cerrno>

#include "core/io/socket_address.hpp"

namespace navfuse::io {

TcpListener::TcpListener(TcpListenerOptions options) : options_(std::move(options)) {
  listen_now();
}

std::string TcpListener::uri_text() const {
  const bool v6 = options_.host.find(':') != std::string::npos;
  return "tcp-listen://" + (v6 ? "[" + options_.host + "]" : options_.host) + ":" +
         std::to_string(options_.port);
}

void TcpListener::listen_now() {
  const SocketAddress address =
      resolve(options_.host, options_.port, SOCK_STREAM, true, uri_text()).front();
  UniqueFd fd(::socket(address.family(), SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  if (!fd) throw TransportError(uri_text() + ": " + errno_text("socket", errno));
  // SO_REUSEADDR: a restarted nav process can bind again while old connections sit in
  // TIME_WAIT (socket(7)).
  const int one = 1;
  (void)::setsockopt(fd.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(fd.get(), address.get(), address.length) != 0) {
    throw TransportError(uri_text() + ": " + errno_text("bind " + to_string(address), errno));
  }
  if (::listen(fd.get(), SOMAXCONN) != 0) {
    throw TransportError(uri_text() + ": " + errno_text("listen", errno));
  }
  SocketAddress bound;
  bound.length = sizeof bound.storage;
  if (::getsockname(fd.get(), bound.get(), &bound.length) == 0) local_port_ = bound.port();
  listen_fd_ = std::move(fd);
}

bool TcpListener::reopen() {
  clients_.clear();
  listen_fd_.reset();
  try {
    listen_now();
  } catch (const TransportError& e) {
    record_error(e.what());
  }
  if (is_open()) ++stats_.reconnects;
  return is_open();
}

void TcpListener::accept_pending() {
  while (listen_fd_) {
    SocketAddress peer;
    peer.length = sizeof peer.storage;
    UniqueFd fd(::accept4(listen_fd_.get(), peer.get(), &peer.length, SOCK_NONBLOCK | SOCK_CLOEXEC));
    if (!fd) {
      // EAGAIN: backlog empty. ECONNABORTED etc.: that client is gone; others may be waiting
      // but the next call will find them (accept(2) lists these as transient).
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
        record_error(uri_text() + ": " + errno_text("accept", errno));
      }
      return;
    }
    if (clients_.size() >= options_.max_clients) {
      record_error(uri_text() + ": refused " + to_string(peer) + ": already " +
                   std::to_string(clients_.size()) + " clients (max_clients)");
      continue;  // fd closes here
    }
    const int one = 1;
    (void)::setsockopt(fd.get(), IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    clients_.push_back(Client{next_id_++, std::move(fd), WriteQueue(options_.queue_bytes), to_string(peer)});
  }
}

void TcpListener::drop(std::size_t index, const std::string& why) {
  record_error(uri_text() + ": client " + clients_[index].name + ": " + why);
  clients_.erase(clients_.begin() + static_cast<std::ptrdiff_t>(index));
}

bool TcpListener::send_to(std::size_t index, std::span<const std::uint8_t> data) {
  Client& c = clients_[index];
  switch (c.queue.write(c.fd.get(), true, data, stats_.bytes_written)) {
    case WriteQueue::Result::kOk:
      return true;
    case WriteQueue::Result::kOverflow:
      ++stats_.clients_dropped;
      stats_.bytes_dropped += data.size();
      drop(index, "not keeping up (" + std::to_string(c.queue.queued_bytes()) +
                      " bytes queued), disconnected");
      return false;
    case WriteQueue::Result::kError:
      break;
  }
  stats_.bytes_dropped += data.size();
  drop(index, errno_text("send", c.queue.error()));
  return false;
}

std::ptrdiff_t TcpListener::write(std::span<const std::uint8_t> data) {
  accept_pending();
  bool delivered = false;
  for (std::size_t i = 0; i < clients_.size();) {
    if (send_to(i, data)) {
      delivered = true;
      ++i;
    }  // else clients_[i] was erased: the next client moved into slot i
  }
  return delivered ? static_cast<std::ptrdiff_t>(data.size()) : 0;
}

std::ptrdiff_t TcpListener::write_to(PeerId peer, std::span<const std::uint8_t> data) {
  for (std::size_t i = 0; i < clients_.size(); ++i) {
    if (clients_[i].id == peer) {
      return send_to(i, data) ? static_cast<std::ptrdiff_t>(data.size()) : 0;
    }
  }
  stats_.bytes_dropped += data.size();
  record_error(uri_text() + ": no client " + std::to_string(peer) + " (disconnected?)");
  return 0;
}

std::ptrdiff_t TcpListener::read(std::span<std::uint8_t> buffer, int timeout_ms) {
  PeerId ignored = kNoPeer;
  return read_from(buffer, timeout_ms, ignored);
}

std::ptrdiff_t TcpListener::read_from(std::span<std::uint8_t> buffer, int timeout_ms,
                                      PeerId& from) {
  from = kNoPeer;
  const Deadline deadline(timeout_ms);
  std::vector<pollfd> fds;
  for (;;) {
    if (!listen_fd_) {  // only after a failed reopen(): nothing to wait on but time
      ::poll(nullptr, 0, deadline.remaining_ms());
      return 0;
    }
    // Slot 0 is the listening socket; slot i + 1 is clients_[i].
    fds.assign(1, pollfd{listen_fd_.get(), POLLIN, 0});
    for (const Client& c : clients_) {
      fds.push_back(pollfd{c.fd.get(), static_cast<short>(POLLIN | (c.queue.empty() ? 0 : POLLOUT)), 0});
    }
    const int ready = ::poll(fds.data(), fds.size(), deadline.remaining_ms());
    if (ready < 0) {
      if (errno == EINTR) continue;
      record_error(uri_text() + ": " + errno_text("poll", errno));
      return 0;
    }
    if (ready == 0) return 0;

    // Flush writable backlogs first (indices stay valid: flushing erases nobody here).
    bool changed = false;
    for (std::size_t i = 0; i < clients_.size(); ++i) {
      if ((fds[i + 1].revents & POLLOUT) &&
          clients_[i].queue.flush(clients_[i].fd.get(), true, stats_.bytes_written) ==
              WriteQueue::Result::kError) {
        drop(i, errno_text("send", clients_[i].queue.error()));
        changed = true;
        break;
      }
    }
    if (changed) continue;  // indices moved: poll again (at once if data is waiting)

    // Read from the first ready client at or after the round-robin position.
    const std::size_t n_clients = clients_.size();
    for (std::size_t k = 0; k < n_clients; ++k) {
      const std::size_t i = (next_reader_ + k) % n_clients;
      if (!(fds[i + 1].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = ::recv(clients_[i].fd.get(), buffer.data(), buffer.size(), MSG_DONTWAIT);
      if (n > 0) {
        stats_.bytes_read += static_cast<std::uint64_t>(n);
        from = clients_[i].id;
        next_reader_ = i + 1;
        return n;
      }
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) continue;
      if (n == 0) {
        clients_.erase(clients_.begin() + static_cast<std::ptrdiff_t>(i));  // orderly close
      } else {
        drop(i, errno_text("recv", errno));
      }
      changed = true;
      break;
    }
    if (fds[0].revents & POLLIN) accept_pending();
    if (!changed && deadline.expired()) return 0;
  }
}

std::string TcpListener::describe() const {
  return uri_text() + " (port " + std::to_string(local_port_) + ", " +
         std::to_string(clients_.size()) + " clients)";
}

}  // namespace navfuse::io
