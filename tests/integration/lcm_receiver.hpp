// Collects messages of one LCM type from one channel, for tests: bounded waits, no threads
// (the test's own loop services the handle).
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

namespace navfuse::test {

template <class Message>
class LcmReceiver {
 public:
  LcmReceiver(lcm::LCM& lcm, const std::string& channel) {
    lcm.subscribe(channel, &LcmReceiver::on_message, this);
  }
  std::vector<Message> messages;

 private:
  void on_message(const lcm::ReceiveBuffer*, const std::string&, const Message* m) { messages.push_back(*m); }
};

// Services `lcm` until `done()` or timeout_ms; returns done().
template <class Done>
bool handle_until(lcm::LCM& lcm, Done done, int timeout_ms) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (!done()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return done();
    lcm.handleTimeout(static_cast<int>(std::min<long>(left.count(), 50)));
  }
  return true;
}

}  // namespace navfuse::test
