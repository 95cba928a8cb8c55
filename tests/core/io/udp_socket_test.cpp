// UDP transport over 127.0.0.1: send, bind and receive, replies by peer, datagram boundaries.
#include "core/io/udp_socket.hpp"

#include <gtest/gtest.h>

#include "core/io/uri.hpp"
#include "tests/core/io/io_test_util.hpp"

namespace navfuse::io {
namespace {

using test::bytes;

std::string as_string(const std::uint8_t* p, std::ptrdiff_t n) {
  return std::string(reinterpret_cast<const char*>(p), static_cast<std::size_t>(n));
}

TEST(UdpSocket, SendReceiveAndReplyToEachSender) {
  auto server = open_transport("udp-listen://127.0.0.1:0", Direction::kBoth);
  const std::uint16_t port = static_cast<UdpSocket&>(*server).local_port();
  ASSERT_NE(port, 0);
  const std::string to_server = "udp://127.0.0.1:" + std::to_string(port);
  auto a = open_transport(to_server, Direction::kBoth);
  auto b = open_transport(to_server, Direction::kBoth);

  std::uint8_t buf[64];
  PeerId pa = kNoPeer;
  PeerId pb = kNoPeer;
  EXPECT_EQ(a->write(bytes("from-a")), 6);
  ASSERT_EQ(server->read_from(buf, 3000, pa), 6);
  EXPECT_EQ(as_string(buf, 6), "from-a");
  EXPECT_EQ(b->write(bytes("from-b")), 6);
  ASSERT_EQ(server->read_from(buf, 3000, pb), 6);
  EXPECT_NE(pa, kNoPeer);
  EXPECT_NE(pa, pb);

  EXPECT_EQ(server->write_to(pa, bytes("to-a")), 4);
  ASSERT_EQ(a->read(buf, 3000), 4);
  EXPECT_EQ(as_string(buf, 4), "to-a");
  EXPECT_EQ(server->write(bytes("last")), 4);  // plain write answers the latest sender (b)
  ASSERT_EQ(b->read(buf, 3000), 4);
  EXPECT_EQ(as_string(buf, 4), "last");
  EXPECT_EQ(a->read(buf, 10), 0);  // a got nothing more

  EXPECT_EQ(server->stats().bytes_read, 12u);
  EXPECT_EQ(server->stats().bytes_written, 8u);
  EXPECT_EQ(a->stats().bytes_written, 6u);
}

TEST(UdpSocket, KeepsDatagramBoundariesAndReportsTruncation) {
  auto server = open_transport("udp-listen://127.0.0.1:0", Direction::kInput);
  auto client = open_transport(
      "udp://127.0.0.1:" + std::to_string(static_cast<UdpSocket&>(*server).local_port()),
      Direction::kOutput);
  client->write(bytes("one"));
  client->write(bytes("two!"));
  client->write(bytes("0123456789"));
  std::uint8_t buf[64];
  EXPECT_EQ(server->read(buf, 3000), 3);
  EXPECT_EQ(server->read(buf, 3000), 4);
  EXPECT_EQ(server->read(std::span(buf, 4), 3000), 4);  // 10-byte datagram, 4-byte buffer
  EXPECT_EQ(server->stats().errors, 1u);
  EXPECT_NE(server->stats().last_error.find("truncated"), std::string::npos);
  EXPECT_EQ(server->read(buf, 10), 0);  // the rest of a truncated datagram is gone
}

TEST(UdpSocket, ListenerWithNoSenderDropsWrites) {
  auto server = open_transport("udp-listen://127.0.0.1:0", Direction::kBoth);
  EXPECT_EQ(server->write(bytes("x")), 0);
  EXPECT_EQ(server->stats().bytes_dropped, 1u);
  EXPECT_TRUE(server->reopen());
  EXPECT_TRUE(server->is_open());
}

}  // namespace
}  // namespace navfuse::io
