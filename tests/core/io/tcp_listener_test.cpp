// TCP listener transport over 127.0.0.1: several clients, replies to the sender, broadcast, and
// a client that never reads being cut off without ever blocking the writer.
#include "core/io/tcp_listener.hpp"

#include <gtest/gtest.h>

#include "core/io/uri.hpp"
#include "tests/core/io/io_test_util.hpp"

namespace navfuse::io {
namespace {

using test::bytes;

std::uint16_t port_of(Transport& t) { return static_cast<TcpListener&>(t).local_port(); }

TEST(TcpListener, RepliesToTheClientThatAsked) {
  auto server = open_transport("tcp-listen://127.0.0.1:0", Direction::kBoth);
  ASSERT_TRUE(server->is_open());
  UniqueFd a = test::connect_loopback(port_of(*server));
  UniqueFd b = test::connect_loopback(port_of(*server));
  ASSERT_TRUE(a && b);

  ASSERT_EQ(::send(a.get(), "from-a", 6, 0), 6);
  PeerId peer_a = kNoPeer;
  EXPECT_EQ(test::read_n(*server, 6, 3000, &peer_a), "from-a");
  ASSERT_EQ(::send(b.get(), "from-b", 6, 0), 6);
  PeerId peer_b = kNoPeer;
  EXPECT_EQ(test::read_n(*server, 6, 3000, &peer_b), "from-b");
  EXPECT_NE(peer_a, kNoPeer);
  EXPECT_NE(peer_a, peer_b);

  EXPECT_EQ(server->write_to(peer_b, bytes("to-b")), 4);
  EXPECT_EQ(server->write_to(peer_a, bytes("to-a")), 4);
  EXPECT_EQ(test::read_fd(a.get(), 4), "to-a");  // each got its own reply, nothing else
  EXPECT_EQ(test::read_fd(b.get(), 4), "to-b");

  EXPECT_EQ(server->write_to(9999, bytes("x")), 0);  // unknown peer
}

TEST(TcpListener, WriteReachesEveryClientAndForgetsClosedOnes) {
  auto server = open_transport("tcp-listen://127.0.0.1:0", Direction::kOutput);
  auto& listener = static_cast<TcpListener&>(*server);
  std::uint8_t buf[8];
  EXPECT_EQ(server->write(bytes("nobody")), 0);  // no clients yet: nothing to deliver to

  UniqueFd a = test::connect_loopback(listener.local_port());
  UniqueFd b = test::connect_loopback(listener.local_port());
  EXPECT_EQ(server->write(bytes("pose")), 4);  // write() accepts the waiting clients itself
  EXPECT_EQ(listener.client_count(), 2u);
  EXPECT_EQ(test::read_fd(a.get(), 4), "pose");
  EXPECT_EQ(test::read_fd(b.get(), 4), "pose");

  a.reset();  // one consumer leaves; the listener notices on read (EOF) and forgets it
  const Deadline deadline(3000);
  while (listener.client_count() == 2 && !deadline.expired()) server->read(buf, 20);
  EXPECT_EQ(listener.client_count(), 1u);
  EXPECT_EQ(server->write(bytes("next")), 4);
  EXPECT_EQ(test::read_fd(b.get(), 4), "next");
}

TEST(TcpListener, MaxClientsRefusesExtraConnections) {
  auto server = open_transport("tcp-listen://127.0.0.1:0?max_clients=1", Direction::kBoth);
  auto& listener = static_cast<TcpListener&>(*server);
  UniqueFd a = test::connect_loopback(listener.local_port());
  UniqueFd b = test::connect_loopback(listener.local_port());
  listener.accept_pending();
  EXPECT_EQ(listener.client_count(), 1u);
  EXPECT_NE(server->stats().last_error.find("max_clients"), std::string::npos);
  char c = 0;
  pollfd p{b.get(), POLLIN, 0};
  ASSERT_EQ(::poll(&p, 1, 3000), 1);
  EXPECT_EQ(::recv(b.get(), &c, 1, 0), 0);  // the extra client was closed
}

TEST(TcpListener, SlowClientIsDroppedWithoutBlockingTheWriter) {
  auto server = open_transport("tcp-listen://127.0.0.1:0?queue_bytes=65536", Direction::kBoth);
  auto& listener = static_cast<TcpListener&>(*server);
  UniqueFd fast = test::connect_loopback(listener.local_port());
  UniqueFd slow = test::connect_loopback(listener.local_port(), 4096);  // never reads
  listener.accept_pending();
  ASSERT_EQ(listener.client_count(), 2u);

  const std::string chunk(16384, 'p');
  std::size_t sent = 0;
  std::size_t received_fast = 0;
  char buf[65536];
  auto drain_fast = [&] {
    ssize_t n = 0;
    while ((n = ::recv(fast.get(), buf, sizeof buf, MSG_DONTWAIT)) > 0) {
      received_fast += static_cast<std::size_t>(n);
    }
  };
  // Each write() returns at once; the slow client's backlog grows until it exceeds the kernel
  // buffers plus queue_bytes, and it is cut off. Bounded: at most 1 GiB.
  for (int i = 0; i < 65536 && server->stats().clients_dropped == 0; ++i) {
    ASSERT_EQ(server->write(bytes(chunk)), static_cast<std::ptrdiff_t>(chunk.size()));
    sent += chunk.size();
    drain_fast();
  }
  EXPECT_EQ(server->stats().clients_dropped, 1u);
  EXPECT_EQ(listener.client_count(), 1u);
  EXPECT_NE(server->stats().last_error.find("not keeping up"), std::string::npos)
      << server->stats().last_error;

  // The fast client, which kept up, got every byte.
  const Deadline deadline(5000);
  std::uint8_t scratch[16];
  while (received_fast < sent && !deadline.expired()) {
    server->read(scratch, 1);  // flushes the fast client's queue as its socket drains
    drain_fast();
  }
  EXPECT_EQ(received_fast, sent);
}

TEST(TcpListener, BindErrorsThrow) {
  auto first = open_transport("tcp-listen://127.0.0.1:0", Direction::kBoth);
  const std::string busy = "tcp-listen://127.0.0.1:" + std::to_string(port_of(*first));
  try {
    open_transport(busy, Direction::kBoth);
    FAIL() << "expected TransportError";
  } catch (const TransportError& e) {
    EXPECT_NE(std::string(e.what()).find("Address already in use"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace navfuse::io
