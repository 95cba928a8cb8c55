// Byte transports: one interface over serial ports, TCP (client and listener), UDP and files, so
// the nav process wires device streams and outputs by URI (DESIGN.md "Command line": `serial:`,
// `tcp://`, `tcp-listen://`, `udp://`, `file:`) without caring which kind it got.
//
// Contract of every transport:
//  - No call blocks longer than the timeout it is given; write() never waits at all (file
//    outputs excepted: regular files do not support non-blocking I/O, POSIX open(2)). A negative
//    timeout counts as 0: there are no infinite waits.
//  - Links that can come back (serial devices, TCP connections) are re-established by the
//    transport itself, with exponential backoff, from inside read()/write()/wait_open(); the
//    caller just keeps calling read(). Losing a link counts in stats().errors, each successful
//    re-establishment in stats().reconnects.
//  - No SIGPIPE: sockets are written with MSG_NOSIGNAL (POSIX send(2)).
//  - Not thread-safe: one thread uses a transport at a time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace navfuse::io {

struct Uri;

// Counters every transport keeps. Bytes are counted at the system-call boundary.
struct TransportStats {
  std::uint64_t bytes_read = 0;
  std::uint64_t bytes_written = 0;    // accepted by the kernel (not merely queued)
  std::uint64_t bytes_dropped = 0;    // given to write() but discarded: link down, queue full
  std::uint64_t errors = 0;           // failed system calls, lost links, refused connections
  std::uint64_t reconnects = 0;       // successful re-opens / re-connects after the first
  std::uint64_t clients_dropped = 0;  // tcp-listen: clients cut off because they fell behind
  std::string last_error;             // most recent error, one line; "" if none yet
};

// Which way the caller uses a transport. Only file: cares (read-only vs. create/truncate);
// every other transport is duplex whatever is asked.
enum class Direction { kInput, kOutput, kBoth };

// Identifies the remote end a read came from, so a reply can go back to it (tcp-listen:
// one id per accepted client; udp listen: one id per sender address). kNoPeer for transports
// with a single remote end. Ids are never reused within one transport.
using PeerId = std::uint64_t;
inline constexpr PeerId kNoPeer = 0;

// read() result for a stream that has ended and will give no more bytes (file at EOF).
inline constexpr std::ptrdiff_t kEndOfStream = -1;

// Thrown for bad URIs and for failures that retrying cannot fix (a file that cannot be opened,
// a port that cannot be bound, a host name that does not resolve). what() is one line.
class TransportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Transport {
 public:
  virtual ~Transport() = default;
  Transport() = default;
  Transport(const Transport&) = delete;
  Transport& operator=(const Transport&) = delete;

  // Reads up to buffer.size() bytes, waiting at most timeout_ms for some to arrive.
  // Returns the byte count (> 0), 0 if nothing arrived in time (including while a link is down
  // and being re-established), or kEndOfStream. Bytes of one call come from one peer only.
  virtual std::ptrdiff_t read(std::span<std::uint8_t> buffer, int timeout_ms) = 0;

  // As read(), also telling which peer sent the bytes (kNoPeer where there is only one).
  // Callers that frame bytes from a multi-client transport keep one framer per peer.
  virtual std::ptrdiff_t read_from(std::span<std::uint8_t> buffer, int timeout_ms, PeerId& from) {
    from = kNoPeer;
    return read(buffer, timeout_ms);
  }

  // Sends `data` without waiting. Returns data.size() when it was sent or queued whole (to at
  // least one peer, for tcp-listen), 0 when it was dropped (link down, queue full, no peer).
  // A message is never cut short: queued stream transports take it whole or not at all.
  virtual std::ptrdiff_t write(std::span<const std::uint8_t> data) = 0;

  // Sends to one peer (a PeerId from read_from()); single-peer transports ignore `peer`.
  virtual std::ptrdiff_t write_to(PeerId peer, std::span<const std::uint8_t> data) {
    (void)peer;
    return write(data);
  }

  // Whether the link is up now (serial device open, TCP connected, socket bound, file open).
  virtual bool is_open() const = 0;

  // Closes and re-opens now, ignoring any backoff. Returns is_open() afterwards.
  virtual bool reopen() = 0;

  // Waits up to timeout_ms for the link to come up (e.g. a TCP connect in progress).
  virtual bool wait_open(int timeout_ms) {
    (void)timeout_ms;
    return is_open();
  }

  // The URI this transport was opened from and its state, e.g. "tcp://127.0.0.1:5000 (connected)".
  virtual std::string describe() const = 0;

  const TransportStats& stats() const { return stats_; }

 protected:
  void record_error(std::string what) {
    ++stats_.errors;
    stats_.last_error = std::move(what);
  }
  TransportStats stats_;
};

// Opens the transport a URI names (see core/io/uri.hpp for the forms and their options).
// Throws TransportError for a bad URI or an unrecoverable failure; a device or peer that is
// merely absent right now is not an error for tcp:// (it connects when the peer appears), but is
// for serial: and file:, so a mistyped path is reported at once.
std::unique_ptr<Transport> open_transport(std::string_view uri, Direction direction);
std::unique_ptr<Transport> open_transport(const Uri& uri, Direction direction);

}  // namespace navfuse::io
