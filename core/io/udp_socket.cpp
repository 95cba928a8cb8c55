// UDP transport (udp_socket.hpp).
#include "core/io/udp_socket.hpp"

#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>

namespace navfuse::io {
namespace {
constexpr std::size_t kMaxPeers = 64;
}  // namespace

UdpSocket::UdpSocket(UdpOptions options) : options_(std::move(options)) { open_socket(); }

std::string UdpSocket::uri_text() const {
  const bool v6 = options_.host.find(':') != std::string::npos;
  return std::string(options_.listen ? "udp-listen://" : "udp://") +
         (v6 ? "[" + options_.host + "]" : options_.host) + ":" + std::to_string(options_.port);
}

void UdpSocket::open_socket() {
  const SocketAddress address =
      resolve(options_.host, options_.port, SOCK_DGRAM, options_.listen, uri_text()).front();
  UniqueFd fd(::socket(address.family(), SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  if (!fd) throw TransportError(uri_text() + ": " + errno_text("socket", errno));
  if (options_.listen) {
    const int one = 1;
    (void)::setsockopt(fd.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd.get(), address.get(), address.length) != 0) {
      throw TransportError(uri_text() + ": " + errno_text("bind " + to_string(address), errno));
    }
  } else {
    // Not connect(2)ed: a connected UDP socket turns an ICMP "port unreachable" into errors on
    // later calls (udp(7)), which for a fire-and-forget output is noise, not information.
    destination_ = address;
  }
  SocketAddress bound;
  bound.length = sizeof bound.storage;
  if (::getsockname(fd.get(), bound.get(), &bound.length) == 0) local_port_ = bound.port();
  fd_ = std::move(fd);
}

bool UdpSocket::reopen() {
  fd_.reset();
  peers_.clear();
  try {
    open_socket();
  } catch (const TransportError& e) {
    record_error(e.what());
  }
  if (is_open()) ++stats_.reconnects;
  return is_open();
}

PeerId UdpSocket::remember(const SocketAddress& sender) {
  const auto it = std::find_if(peers_.begin(), peers_.end(),
                               [&](const Peer& p) { return p.address == sender; });
  Peer peer = it != peers_.end() ? *it : Peer{next_id_++, sender};
  if (it != peers_.end()) peers_.erase(it);
  if (peers_.size() >= kMaxPeers) peers_.erase(peers_.begin());  // forget the oldest
  peers_.push_back(peer);
  return peer.id;
}

std::ptrdiff_t UdpSocket::read(std::span<std::uint8_t> buffer, int timeout_ms) {
  PeerId ignored = kNoPeer;
  return read_from(buffer, timeout_ms, ignored);
}

std::ptrdiff_t UdpSocket::read_from(std::span<std::uint8_t> buffer, int timeout_ms, PeerId& from) {
  from = kNoPeer;
  if (!fd_) {
    ::poll(nullptr, 0, std::max(timeout_ms, 0));
    return 0;
  }
  const Deadline deadline(timeout_ms);
  for (;;) {
    pollfd p{fd_.get(), POLLIN, 0};
    const int ready = ::poll(&p, 1, deadline.remaining_ms());
    if (ready < 0 && errno != EINTR) {
      record_error(uri_text() + ": " + errno_text("poll", errno));
      return 0;
    }
    if (ready == 0) return 0;
    SocketAddress sender;
    sender.length = sizeof sender.storage;
    // MSG_TRUNC makes recvfrom(2) return the datagram's real length, so truncation is seen.
    const ssize_t n = ::recvfrom(fd_.get(), buffer.data(), buffer.size(), MSG_DONTWAIT | MSG_TRUNC,
                                 sender.get(), &sender.length);
    if (n < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
        record_error(uri_text() + ": " + errno_text("recvfrom", errno));
      }
      if (deadline.expired()) return 0;
      continue;
    }
    std::size_t got = static_cast<std::size_t>(n);
    if (got > buffer.size()) {
      record_error(uri_text() + ": datagram of " + std::to_string(got) + " bytes truncated to " +
                   std::to_string(buffer.size()));
      got = buffer.size();
    }
    stats_.bytes_read += got;
    from = remember(sender);
    if (got == 0) {  // an empty datagram is legal but carries nothing to return
      if (deadline.expired()) return 0;
      continue;
    }
    return static_cast<std::ptrdiff_t>(got);
  }
}

std::ptrdiff_t UdpSocket::send(const SocketAddress& to, std::span<const std::uint8_t> data) {
  if (!fd_) {
    stats_.bytes_dropped += data.size();
    return 0;
  }
  const ssize_t n = ::sendto(fd_.get(), data.data(), data.size(), MSG_DONTWAIT | MSG_NOSIGNAL,
                             to.get(), to.length);
  if (n < 0) {
    // EAGAIN: the socket buffer is full; a datagram is dropped rather than waited for.
    record_error(uri_text() + ": " + errno_text("sendto " + to_string(to), errno));
    stats_.bytes_dropped += data.size();
    return 0;
  }
  stats_.bytes_written += static_cast<std::uint64_t>(n);
  return n;
}

std::ptrdiff_t UdpSocket::write(std::span<const std::uint8_t> data) {
  if (!options_.listen) return send(destination_, data);
  if (peers_.empty()) {
    stats_.bytes_dropped += data.size();
    return 0;
  }
  return send(peers_.back().address, data);
}

std::ptrdiff_t UdpSocket::write_to(PeerId peer, std::span<const std::uint8_t> data) {
  if (!options_.listen) return send(destination_, data);
  for (const Peer& p : peers_) {
    if (p.id == peer) return send(p.address, data);
  }
  stats_.bytes_dropped += data.size();
  record_error(uri_text() + ": no peer " + std::to_string(peer));
  return 0;
}

std::string UdpSocket::describe() const {
  return uri_text() + " (local port " + std::to_string(local_port_) + ")";
}

}  // namespace navfuse::io
