// TCP client transport over 127.0.0.1: connect, exchange, lose the peer, reconnect.
#include "core/io/tcp_client.hpp"

#include <gtest/gtest.h>

#include "core/io/tcp_listener.hpp"
#include "core/io/uri.hpp"
#include "tests/core/io/io_test_util.hpp"

namespace navfuse::io {
namespace {

using test::bytes;

std::unique_ptr<TcpListener> listen_on(std::uint16_t port) {
  return std::make_unique<TcpListener>(TcpListenerOptions{"127.0.0.1", port, 16, 262144});
}

TEST(TcpClient, ConnectsAndExchanges) {
  auto server = listen_on(0);
  auto client = open_transport("tcp://127.0.0.1:" + std::to_string(server->local_port()),
                               Direction::kBoth);
  ASSERT_TRUE(client->wait_open(3000)) << client->stats().last_error;
  EXPECT_NE(client->describe().find("(connected)"), std::string::npos);

  EXPECT_EQ(client->write(bytes("hello")), 5);
  PeerId from = kNoPeer;
  EXPECT_EQ(test::read_n(*server, 5, 3000, &from), "hello");
  EXPECT_NE(from, kNoPeer);
  EXPECT_EQ(server->write_to(from, bytes("world")), 5);
  EXPECT_EQ(test::read_n(*client, 5), "world");

  EXPECT_EQ(client->stats().bytes_written, 5u);
  EXPECT_EQ(client->stats().bytes_read, 5u);
  EXPECT_EQ(client->stats().reconnects, 0u);
}

TEST(TcpClient, ReconnectsWhenThePeerComesBack) {
  auto server = listen_on(0);
  const std::uint16_t port = server->local_port();
  auto client = open_transport(
      "tcp://127.0.0.1:" + std::to_string(port) + "?reconnect_ms=5&max_reconnect_ms=20",
      Direction::kBoth);
  ASSERT_TRUE(client->wait_open(3000));
  server->accept_pending();
  ASSERT_EQ(server->client_count(), 1u);

  server.reset();  // the peer goes away (listener and connection closed)
  std::uint8_t buf[16];
  const Deadline noticed(3000);
  while (client->is_open() && !noticed.expired()) client->read(buf, 50);
  EXPECT_FALSE(client->is_open());
  EXPECT_GE(client->stats().errors, 1u);
  EXPECT_EQ(client->write(bytes("drop")), 0);  // nothing to send to: dropped, not queued
  EXPECT_EQ(client->stats().bytes_dropped, 4u);

  server = listen_on(port);  // the peer restarts on the same port
  ASSERT_TRUE(client->wait_open(3000)) << client->stats().last_error;
  EXPECT_EQ(client->stats().reconnects, 1u);
  EXPECT_EQ(client->write(bytes("again")), 5);
  EXPECT_EQ(test::read_n(*server, 5), "again");
}

TEST(TcpClient, RefusedConnectionIsRetriedWithinTheTimeout) {
  const std::uint16_t port = test::unused_port();
  auto client = open_transport(
      "tcp://127.0.0.1:" + std::to_string(port) + "?reconnect_ms=5&max_reconnect_ms=10",
      Direction::kBoth);
  std::uint8_t buf[16];
  EXPECT_EQ(client->read(buf, 100), 0);  // returns at the timeout, having retried
  EXPECT_FALSE(client->is_open());
  EXPECT_GE(client->stats().errors, 2u);
  EXPECT_NE(client->stats().last_error.find("refused"), std::string::npos)
      << client->stats().last_error;
  EXPECT_FALSE(client->wait_open(20));
}

TEST(TcpClient, UnresolvableHostThrows) {
  EXPECT_THROW(open_transport("tcp://no-such-host.invalid:5000", Direction::kBoth),
               TransportError);
}

}  // namespace
}  // namespace navfuse::io
