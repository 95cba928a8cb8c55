// Serial port transport through a pseudo-terminal pair (openpty(3)): the test holds the master
// side as "the device", the transport opens the slave path. A pty slave path dies with its
// master, so losing and regaining the device is tested through a symlink that is re-pointed to
// a new pty, as udev re-points /dev/serial/by-id/... when a USB adapter is plugged back in.
#include "core/io/serial_port.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "core/io/uri.hpp"
#include "tests/core/io/io_test_util.hpp"

namespace navfuse::io {
namespace {

using test::bytes;

struct Pty {
  UniqueFd master;
  UniqueFd slave;  // held only until the transport has opened the slave path
  std::string slave_path;
};

Pty make_pty() {
  int master = -1;
  int slave = -1;
  char name[256] = {};
  if (::openpty(&master, &slave, name, nullptr, nullptr) != 0) return {};
  return Pty{UniqueFd(master), UniqueFd(slave), name};
}

class SerialPortTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("navfuse_serial_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    link_ = (dir_ / "tty").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Points the symlink at `target` atomically (rename(2) over the old link).
  void point_link_to(const std::string& target) {
    const std::string tmp = link_ + ".new";
    std::filesystem::remove(tmp);
    ASSERT_EQ(::symlink(target.c_str(), tmp.c_str()), 0);
    ASSERT_EQ(::rename(tmp.c_str(), link_.c_str()), 0);
  }

  std::filesystem::path dir_;
  std::string link_;
};

TEST_F(SerialPortTest, RawBytesBothWays) {
  Pty pty = make_pty();
  ASSERT_TRUE(pty.master) << "openpty failed";
  point_link_to(pty.slave_path);
  auto port = open_transport("serial:" + link_ + "?baud=921600", Direction::kBoth);
  pty.slave.reset();
  ASSERT_TRUE(port->is_open());

  // Every byte value, including those a cooked terminal would eat or translate (CR, NL,
  // ^C, ^S/^Q, ^D, DEL): raw mode must pass them unchanged in both directions.
  std::string all(256, '\0');
  for (int i = 0; i < 256; ++i) all[static_cast<std::size_t>(i)] = static_cast<char>(i);
  ASSERT_EQ(::write(pty.master.get(), all.data(), all.size()), 256);
  EXPECT_EQ(test::read_n(*port, 256), all);

  EXPECT_EQ(port->write(bytes(all)), 256);
  EXPECT_EQ(test::read_fd(pty.master.get(), 256), all);

  EXPECT_EQ(port->stats().bytes_read, 256u);
  EXPECT_EQ(port->stats().bytes_written, 256u);
  EXPECT_EQ(port->stats().errors, 0u);
  std::uint8_t buf[16];
  EXPECT_EQ(port->read(buf, 10), 0);  // nothing more: times out with 0
}

TEST_F(SerialPortTest, ReopensWhenTheDeviceComesBack) {
  Pty first = make_pty();
  ASSERT_TRUE(first.master);
  point_link_to(first.slave_path);
  auto port = open_transport("serial:" + link_ + "?baud=115200&reconnect_ms=5&max_reconnect_ms=20",
                             Direction::kBoth);
  first.slave.reset();
  ASSERT_EQ(::write(first.master.get(), "one", 3), 3);
  EXPECT_EQ(test::read_n(*port, 3), "one");

  // Unplug: the by-id link disappears with the device (pointing it nowhere also keeps the
  // transport from opening some other process's pty that reuses the freed number), then the
  // master goes away; the transport notices on its next read.
  point_link_to((dir_ / "unplugged").string());
  first.master.reset();
  std::uint8_t buf[16];
  EXPECT_EQ(port->read(buf, 50), 0);
  EXPECT_FALSE(port->is_open());
  EXPECT_GE(port->stats().errors, 1u);
  // "device lost", then failed re-open attempts while the link points nowhere.
  EXPECT_NE(port->stats().last_error.find(link_), std::string::npos) << port->stats().last_error;
  EXPECT_EQ(port->write(bytes("lost")), 0);  // dropped while the device is away
  EXPECT_EQ(port->stats().bytes_dropped, 4u);

  // Plug back in: a new pty appears under the same (symlink) path.
  Pty second = make_pty();
  ASSERT_TRUE(second.master);
  point_link_to(second.slave_path);
  ASSERT_TRUE(port->wait_open(3000)) << port->stats().last_error;
  second.slave.reset();
  EXPECT_EQ(port->stats().reconnects, 1u);
  ASSERT_EQ(::write(second.master.get(), "two", 3), 3);
  EXPECT_EQ(test::read_n(*port, 3), "two");
  EXPECT_EQ(port->write(bytes("back")), 4);
  EXPECT_EQ(test::read_fd(second.master.get(), 4), "back");
}

TEST_F(SerialPortTest, ExplicitReopen) {
  Pty pty = make_pty();
  ASSERT_TRUE(pty.master);
  point_link_to(pty.slave_path);
  auto port = open_transport("serial:" + link_, Direction::kBoth);
  pty.slave.reset();
  EXPECT_TRUE(port->reopen());
  EXPECT_EQ(port->stats().reconnects, 1u);
  ASSERT_EQ(::write(pty.master.get(), "x", 1), 1);
  EXPECT_EQ(test::read_n(*port, 1), "x");
}

TEST_F(SerialPortTest, OpenErrorsNameThePath) {
  const std::string missing = (dir_ / "ttyNOPE").string();
  try {
    open_transport("serial:" + missing, Direction::kBoth);
    FAIL() << "expected TransportError";
  } catch (const TransportError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  // A regular file is not a terminal: tcgetattr fails and says so.
  const std::string plain = (dir_ / "plain").string();
  std::fclose(std::fopen(plain.c_str(), "w"));
  try {
    open_transport("serial:" + plain, Direction::kBoth);
    FAIL() << "expected TransportError";
  } catch (const TransportError& e) {
    EXPECT_NE(std::string(e.what()).find("tcgetattr"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace navfuse::io
