// Serial port transport: raw 8N1, no flow control, non-blocking with poll(2), re-opened when
// the device disappears (e.g. a USB adapter unplugged and plugged back in).
#pragma once

#include <cstddef>
#include <string>

#include "core/io/reconnect_backoff.hpp"
#include "core/io/transport.hpp"
#include "core/io/unique_fd.hpp"
#include "core/io/write_queue.hpp"

namespace navfuse::io {

// The rates termios(3) can set on Linux (the Bnnn constants of <termios.h>).
inline constexpr long kStandardBaudRates[] = {
    1200,   2400,   4800,   9600,   19200,   38400,   57600,   115200,  230400,  460800,
    500000, 576000, 921600, 1000000, 1152000, 1500000, 2000000, 2500000, 3000000, 3500000, 4000000};
bool is_standard_baud_rate(long baud);

struct SerialOptions {
  std::string path;           // device node, e.g. /dev/ttyUSB0, or a symlink such as
                              // /dev/serial/by-id/..., which survives re-enumeration
  long baud = 115200;         // one of kStandardBaudRates
  int reconnect_ms = 500;     // first retry after the device is lost; doubles up to the cap
  int max_reconnect_ms = 5000;
  std::size_t queue_bytes = 65536;  // output queue when the UART is slower than write() calls
};

class SerialPort : public Transport {
 public:
  // Opens the device now; throws TransportError if that fails (a wrong path shows at once).
  explicit SerialPort(SerialOptions options);

  std::ptrdiff_t read(std::span<std::uint8_t> buffer, int timeout_ms) override;
  std::ptrdiff_t write(std::span<const std::uint8_t> data) override;
  bool is_open() const override { return static_cast<bool>(fd_); }
  bool reopen() override;
  bool wait_open(int timeout_ms) override;
  std::string describe() const override;

 private:
  bool open_device();             // one attempt; records the error on failure
  void lost(const std::string& why);  // closes and schedules a re-open
  bool retry_if_due();            // re-opens if the backoff allows; returns is_open()

  SerialOptions options_;
  UniqueFd fd_;
  WriteQueue queue_;
  ReconnectBackoff backoff_;
  bool ever_opened_ = false;
};

}  // namespace navfuse::io
