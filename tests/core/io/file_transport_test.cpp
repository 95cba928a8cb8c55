// File transport: output truncates, reopen appends, input reads to kEndOfStream, errors name the
// path.
#include "core/io/file_transport.hpp"

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/uri.hpp"
#include "tests/core/io/io_test_util.hpp"

namespace navfuse::io {
namespace {

using test::bytes;

class FileTransportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("navfuse_file_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string contents(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::filesystem::path dir_;
};

TEST_F(FileTransportTest, OutputTruncatesThenReopenAppends) {
  const auto path = dir_ / "out.bin";
  std::ofstream(path) << "old contents";
  auto out = open_transport("file:" + path.string(), Direction::kOutput);
  EXPECT_TRUE(out->is_open());
  EXPECT_EQ(out->write(bytes("abc")), 3);
  EXPECT_EQ(contents(path), "abc");  // truncated, written through at once
  EXPECT_TRUE(out->reopen());
  EXPECT_EQ(out->write(bytes("def")), 3);
  EXPECT_EQ(contents(path), "abcdef");
  EXPECT_EQ(out->stats().bytes_written, 6u);
  EXPECT_EQ(out->stats().reconnects, 1u);
  std::uint8_t buf[4];
  EXPECT_EQ(out->read(buf, 0), kEndOfStream);  // an output has nothing to read
}

TEST_F(FileTransportTest, InputReadsToEndOfStream) {
  const auto path = dir_ / "in.bin";
  std::string data(10000, '\0');
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<char>(i * 7);
  std::ofstream(path, std::ios::binary) << data;
  auto in = open_transport("file:" + path.string(), Direction::kInput);
  EXPECT_EQ(test::read_n(*in, data.size() + 1), data);  // stops at kEndOfStream
  std::uint8_t buf[16];
  EXPECT_EQ(in->read(buf, 10), kEndOfStream);
  EXPECT_EQ(in->stats().bytes_read, data.size());
  EXPECT_EQ(in->write(bytes("x")), 0);  // an input is not written
  EXPECT_NE(in->describe().find("at end"), std::string::npos);
  EXPECT_TRUE(in->reopen());  // starts again from the beginning
  EXPECT_EQ(test::read_n(*in, 5), data.substr(0, 5));
}

TEST_F(FileTransportTest, ErrorsNameThePath) {
  const std::string missing = (dir_ / "absent.bin").string();
  try {
    open_transport("file:" + missing, Direction::kInput);
    FAIL() << "expected TransportError";
  } catch (const TransportError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(open_transport("file:" + (dir_ / "no/such/dir/x").string(), Direction::kOutput),
               TransportError);
  EXPECT_THROW(open_transport("file:" + missing, Direction::kBoth), TransportError);
}

TEST_F(FileTransportTest, PipeInputWaitsOnlyUntilTheTimeout) {
  // A FIFO has no data until its writer sends some: read() must return 0 at the timeout.
  const auto fifo = dir_ / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  UniqueFd keep_open(::open(fifo.c_str(), O_RDWR | O_NONBLOCK));  // so open(O_RDONLY) won't wait
  ASSERT_TRUE(keep_open);
  auto in = open_transport("file:" + fifo.string(), Direction::kInput);
  std::uint8_t buf[8];
  EXPECT_EQ(in->read(buf, 20), 0);
  ASSERT_EQ(::write(keep_open.get(), "hi", 2), 2);
  EXPECT_EQ(test::read_n(*in, 2), "hi");
}

}  // namespace
}  // namespace navfuse::io
