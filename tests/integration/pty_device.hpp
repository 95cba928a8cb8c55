// A simulated serial device for tests: the test writes the device's bytes into a pty master
// while the process under test opens the slave through a symlink, which the test re-points to a
// new pty to unplug and replug the device (as udev re-points /dev/serial/by-id/...).
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/io/unique_fd.hpp"

namespace navfuse::test {

class PtyDevice {
 public:
  explicit PtyDevice(std::string link) : link_(std::move(link)) { plug(); }

  // A new pty appears under the link.
  bool plug() {
    int master = -1;
    int slave = -1;
    char name[256] = {};
    if (::openpty(&master, &slave, name, nullptr, nullptr) != 0) return false;
    ::fcntl(master, F_SETFL, ::fcntl(master, F_GETFL) | O_NONBLOCK);  // writes are bounded
    // Not inherited by the processes the test starts: a child holding the master would keep the
    // "device" plugged in after unplug().
    ::fcntl(master, F_SETFD, FD_CLOEXEC);
    ::fcntl(slave, F_SETFD, FD_CLOEXEC);
    master_.reset(master);
    slave_.reset(slave);  // held until the process under test has opened the slave (release())
    return point_link_to(name);
  }
  // The device disappears: the link points nowhere, then the pty goes away.
  void unplug() {
    point_link_to(link_ + ".unplugged");
    slave_.reset();
    master_.reset();
  }
  void release_slave() { slave_.reset(); }
  int master() const { return master_.get(); }
  const std::string& link() const { return link_; }

  // Writes all of `data` (bounded: a stalled reader fails the write rather than hanging).
  bool write_all(const std::uint8_t* data, std::size_t size) {
    std::size_t done = 0;
    io::Deadline deadline(5000);
    while (done < size && !deadline.expired()) {
      pollfd p{master_.get(), POLLOUT, 0};
      if (::poll(&p, 1, deadline.remaining_ms()) <= 0) continue;
      const ssize_t n = ::write(master_.get(), data + done, size - done);
      if (n > 0) {
        done += static_cast<std::size_t>(n);
      } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
        return false;
      }
    }
    return done == size;
  }

 private:
  bool point_link_to(const std::string& target) {
    const std::string tmp = link_ + ".new";
    std::remove(tmp.c_str());
    return ::symlink(target.c_str(), tmp.c_str()) == 0 && ::rename(tmp.c_str(), link_.c_str()) == 0;
  }

  std::string link_;
  io::UniqueFd master_;
  io::UniqueFd slave_;
};

}  // namespace navfuse::test
