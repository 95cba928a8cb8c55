// Serial port transport (serial_port.hpp).
//
// Setup follows termios(3): cfmakeraw() for raw mode (no echo, no canonical line editing, no
// CR/NL translation, 8 data bits), then CLOCAL (ignore modem lines: USB adapters and ptys have
// none), CREAD, no parity, one stop bit, no RTS/CTS; VMIN = VTIME = 0 so read(2) returns at once
// with what is there, the waiting being done by poll(2) with the caller's timeout.
//
// A device that goes away (USB unplug, pty master closed) shows as POLLHUP/POLLERR, read(2)
// failing with EIO, or read(2) returning 0 after poll(2) reported the descriptor readable
// (termios(3): a hung-up terminal reads as end of file). The descriptor is then closed and the
// path re-opened with backoff, so a by-id symlink that reappears is picked up again.
#include "core/io/serial_port.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <termios.h>

#include <algorithm>
#include <cerrno>
#include <optional>

namespace navfuse::io {
namespace {

std::optional<speed_t> termios_speed(long baud) {
  switch (baud) {
    case 1200: return B1200;
    case 2400: return B2400;
    case 4800: return B4800;
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 500000: return B500000;
    case 576000: return B576000;
    case 921600: return B921600;
    case 1000000: return B1000000;
    case 1152000: return B1152000;
    case 1500000: return B1500000;
    case 2000000: return B2000000;
    case 2500000: return B2500000;
    case 3000000: return B3000000;
    case 3500000: return B3500000;
    case 4000000: return B4000000;
    default: return std::nullopt;
  }
}

}  // namespace

bool is_standard_baud_rate(long baud) {
  return std::find(std::begin(kStandardBaudRates), std::end(kStandardBaudRates), baud) !=
         std::end(kStandardBaudRates);
}

SerialPort::SerialPort(SerialOptions options)
    : options_(std::move(options)),
      queue_(options_.queue_bytes),
      backoff_(options_.reconnect_ms, options_.max_reconnect_ms) {
  if (!termios_speed(options_.baud)) {
    throw TransportError(describe() + ": unsupported baud rate " + std::to_string(options_.baud));
  }
  if (!open_device()) throw TransportError("serial:" + options_.path + ": " + stats_.last_error);
}

bool SerialPort::open_device() {
  // O_NOCTTY: never become this terminal's controlling process (a hang-up would SIGHUP us).
  // O_NONBLOCK: open(2) must not wait for carrier detect; reads and writes never block.
  UniqueFd fd(::open(options_.path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC));
  if (!fd) {
    record_error(errno_text("open " + options_.path, errno));
    return false;
  }
  termios tio{};
  if (::tcgetattr(fd.get(), &tio) != 0) {
    record_error(errno_text("tcgetattr " + options_.path, errno));
    return false;
  }
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CRTSCTS | CSIZE);
  tio.c_cflag |= CS8;
  tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  const speed_t speed = *termios_speed(options_.baud);
  if (::cfsetispeed(&tio, speed) != 0 || ::cfsetospeed(&tio, speed) != 0 ||
      ::tcsetattr(fd.get(), TCSANOW, &tio) != 0) {
    record_error(errno_text("tcsetattr " + options_.path, errno));
    return false;
  }
  // Exclusive mode (tty_ioctl(4) TIOCEXCL): a second opener, e.g. a modem manager probing new
  // USB serial devices, gets EBUSY instead of stealing bytes. Best effort.
  (void)::ioctl(fd.get(), TIOCEXCL);

  fd_ = std::move(fd);
  queue_.clear();
  backoff_.succeeded();
  if (ever_opened_) ++stats_.reconnects;
  ever_opened_ = true;
  return true;
}

void SerialPort::lost(const std::string& why) {
  record_error(options_.path + ": device lost: " + why);
  fd_.reset();
  queue_.clear();
  backoff_.failed();
}

bool SerialPort::retry_if_due() {
  if (fd_) return true;
  if (!backoff_.due()) return false;
  if (!open_device()) backoff_.failed();
  return is_open();
}

bool SerialPort::reopen() {
  fd_.reset();
  if (!open_device()) backoff_.failed();
  return is_open();
}

bool SerialPort::wait_open(int timeout_ms) {
  const Deadline deadline(timeout_ms);
  while (!retry_if_due()) {
    if (deadline.expired()) return false;
    ::poll(nullptr, 0, std::min(deadline.remaining_ms(), ms_until(backoff_.next_attempt())));
  }
  return true;
}

std::ptrdiff_t SerialPort::read(std::span<std::uint8_t> buffer, int timeout_ms) {
  const Deadline deadline(timeout_ms);
  for (;;) {
    if (!retry_if_due()) {  // device absent: wait for the next attempt or the deadline
      if (deadline.expired()) return 0;
      ::poll(nullptr, 0, std::min(deadline.remaining_ms(), ms_until(backoff_.next_attempt())));
      continue;
    }
    pollfd p{fd_.get(), static_cast<short>(POLLIN | (queue_.empty() ? 0 : POLLOUT)), 0};
    const int ready = ::poll(&p, 1, deadline.remaining_ms());
    if (ready < 0) {
      if (errno == EINTR) continue;
      record_error(errno_text("poll", errno));
      return 0;
    }
    if (ready == 0) return 0;
    if ((p.revents & POLLOUT) && queue_.flush(fd_.get(), false, stats_.bytes_written) ==
                                     WriteQueue::Result::kError) {
      lost(errno_text("write", queue_.error()));
      continue;
    }
    if (p.revents & (POLLIN | POLLHUP | POLLERR | POLLNVAL)) {
      const ssize_t n = ::read(fd_.get(), buffer.data(), buffer.size());
      if (n > 0) {
        stats_.bytes_read += static_cast<std::uint64_t>(n);
        return n;
      }
      if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
      lost(n == 0 ? "hang-up" : errno_text("read", errno));
    }
    if (deadline.expired()) return 0;
  }
}

std::ptrdiff_t SerialPort::write(std::span<const std::uint8_t> data) {
  if (!retry_if_due()) {
    stats_.bytes_dropped += data.size();
    return 0;
  }
  switch (queue_.write(fd_.get(), false, data, stats_.bytes_written)) {
    case WriteQueue::Result::kOk:
      return static_cast<std::ptrdiff_t>(data.size());
    case WriteQueue::Result::kOverflow:
      stats_.bytes_dropped += data.size();
      record_error(options_.path + ": output queue full, message dropped");
      return 0;
    case WriteQueue::Result::kError:
      break;
  }
  lost(errno_text("write", queue_.error()));
  stats_.bytes_dropped += data.size();
  return 0;
}

std::string SerialPort::describe() const {
  return "serial:" + options_.path + "?baud=" + std::to_string(options_.baud) +
         (fd_ ? " (open)" : " (closed)");
}

}  // namespace navfuse::io
