// A FusionEngine client of the nav process's --fe-out tcp-listen link, as software written for a
// Point One device would be: it reads and frames the stream on its own thread (a client that
// stops reading would be cut off as too slow) and sends commands.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "core/io/unique_fd.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/messages_control.hpp"
#include "frontends/fusionengine/messages_solution.hpp"
#include "frontends/fusionengine/payload_reader.hpp"
#include "frontends/fusionengine/writer.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {

class FeClient {
 public:
  struct Received {
    std::vector<std::int64_t> pose_times_ns;  // p1_time of every Pose, in arrival order
    std::vector<frontends::fusionengine::CommandResponseMessage> responses;
    std::uint64_t frames = 0;
    // Header sequence number of every frame, in arrival order.
    std::vector<std::uint32_t> sequences;
    // Type and payload of every frame other than the solution stream (Pose, PoseAux, GNSSInfo,
    // IMUOutput): status, version, events, command responses.
    struct Other {
      std::uint16_t type = 0;
      std::vector<std::uint8_t> payload;
    };
    std::vector<Other> others;
    std::size_t count(frontends::fusionengine::MessageType type) const {
      std::size_t n = 0;
      for (const auto& o : others) n += o.type == frontends::fusionengine::to_u16(type) ? 1 : 0;
      return n;
    }
  };

  // Connects to 127.0.0.1:port, retrying up to timeout_ms while the listener comes up.
  bool connect(std::uint16_t port, int timeout_ms) {
    fd_ = connect_loopback(port, timeout_ms);
    if (!fd_) return false;
    reader_ = std::thread([this] { read_loop(); });
    return true;
  }
  ~FeClient() {
    stop_ = true;
    if (reader_.joinable()) reader_.join();
  }

  template <class M>
  std::uint32_t send(M msg) {
    std::vector<std::uint8_t> bytes;
    const std::uint32_t sequence = writer_.next_sequence();
    writer_.append(std::move(msg), bytes);
    ::send(fd_.get(), bytes.data(), bytes.size(), MSG_NOSIGNAL);
    return sequence;
  }

  Received snapshot() {
    std::lock_guard lock(mutex_);
    return received_;
  }
  bool closed() const { return closed_; }

 private:
  void read_loop() {
    std::vector<std::uint8_t> buf(65536);
    while (!stop_) {
      pollfd p{fd_.get(), POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      const ssize_t n = ::recv(fd_.get(), buf.data(), buf.size(), 0);
      if (n <= 0) {
        closed_ = true;
        return;
      }
      std::lock_guard lock(mutex_);
      framer_.feed(std::span<const std::uint8_t>(buf.data(), static_cast<std::size_t>(n)), [&](const frontends::fusionengine::Frame& f) {
        ++received_.frames;
        received_.sequences.push_back(f.header.sequence);
        keep_other(f);
        frontends::fusionengine::PayloadReader r(f.payload);
        if (f.header.message_type == frontends::fusionengine::to_u16(frontends::fusionengine::MessageType::kPose)) {
          frontends::fusionengine::PoseMessage m;
          m.visit(r);
          if (r.ok()) received_.pose_times_ns.push_back(m.p1_time.ns());
        } else if (f.header.message_type == frontends::fusionengine::to_u16(frontends::fusionengine::MessageType::kCommandResponse)) {
          frontends::fusionengine::CommandResponseMessage m;
          m.visit(r);
          if (r.ok()) received_.responses.push_back(m);
        }
      });
    }
  }

  void keep_other(const frontends::fusionengine::Frame& f) {
    using frontends::fusionengine::MessageType;
    switch (static_cast<MessageType>(f.header.message_type)) {
      case MessageType::kPose:
      case MessageType::kPoseAux:
      case MessageType::kGnssInfo:
      case MessageType::kImuOutput: return;
      default: received_.others.push_back({f.header.message_type, {f.payload.begin(), f.payload.end()}});
    }
  }

  io::UniqueFd fd_;
  frontends::fusionengine::FusionEngineWriter writer_;
  frontends::fusionengine::Framer framer_;
  std::mutex mutex_;
  Received received_;
  std::thread reader_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> closed_{false};
};

}  // namespace navfuse::test
