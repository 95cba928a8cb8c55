// Output files (issue 15, items 1, 2, 7): a regular file appears only complete; what navfuse did
// not create (a FIFO, a terminal, a symlink) is written in place and survives; write errors
// (ENOSPC, EPIPE) are CommandErrors; an output that is an input, or two outputs on one file, are
// refused. Every special file is made in the test's scratch directory (a pty's slave and
// /dev/full are reached through links there), so a broken OutputFile could only replace those.
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "apps/common/command_error.hpp"
#include "apps/output/output_file.hpp"
#include "apps/output/output_paths.hpp"
#include "cli_runner.hpp"
#include "test_files.hpp"

namespace navfuse::apps {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_cli;
using testing::scratch_dir;
using testing::write_text;

bool is_link(const fs::path& p) { return fs::is_symlink(fs::symlink_status(p)); }

// What arrives on `fd` within `timeout_ms`, until the writer closes (POLLHUP). Bounded, so a
// writer that never comes (an OutputFile that replaced the FIFO) fails the test, not hangs it.
std::string read_until_closed(int fd, int timeout_ms) {
  std::string got;
  for (int waited = 0; waited < timeout_ms; waited += 10) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 10) <= 0) continue;
    char buf[256];
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n > 0) got.append(buf, static_cast<std::size_t>(n));
    if (n <= 0 && (p.revents & POLLHUP) != 0) break;
  }
  return got;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const CommandError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputFile, AppearsOnlyOnCommit) {
  const auto dir = scratch_dir();
  const auto path = dir / "out.bin";
  {
    OutputFile f(path.string());
    EXPECT_FALSE(f.in_place());
    f.write(std::string_view("abc"));
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(fs::exists(path.string() + ".partial"));
    f.commit();
  }
  EXPECT_EQ(read_text(path), "abc");
  EXPECT_FALSE(fs::exists(path.string() + ".partial"));
}

TEST(OutputFile, AbandonedFileLeavesNothing) {
  const auto dir = scratch_dir();
  const auto path = dir / "out.bin";
  try {
    OutputFile f(path.string());
    f.write(std::string_view("half"));
    throw std::runtime_error("run failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path.string() + ".partial"));
}

TEST(OutputFile, UnwritableDirectoryIsACommandErrorNamingThePath) {
  const std::string e = error_of([] { OutputFile f("/nonexistent-dir/out.bin"); });
  EXPECT_NE(e.find("/nonexistent-dir/out.bin"), std::string::npos) << e;
}

TEST(OutputFile, SymlinkToAFileKeepsTheLinkAndReplacesTheTarget) {
  const auto dir = scratch_dir();
  write_text(dir / "target.csv", "old");
  fs::create_symlink("target.csv", dir / "link.csv");
  {
    OutputFile f((dir / "link.csv").string());
    EXPECT_FALSE(f.in_place());
    f.write(std::string_view("new"));
    EXPECT_EQ(read_text(dir / "target.csv"), "old") << "replaced only when complete";
    f.commit();
  }
  EXPECT_TRUE(is_link(dir / "link.csv"));
  EXPECT_EQ(read_text(dir / "target.csv"), "new");
  EXPECT_FALSE(fs::exists(dir / "link.csv.partial"));
  EXPECT_FALSE(fs::exists(dir / "target.csv.partial"));
}

TEST(OutputFile, DanglingSymlinkIsRefusedNotReplaced) {
  const auto dir = scratch_dir();
  fs::create_symlink("missing.csv", dir / "link.csv");
  const std::string e = error_of([&] { OutputFile f((dir / "link.csv").string()); });
  EXPECT_NE(e.find("symbolic link"), std::string::npos) << e;
  EXPECT_TRUE(is_link(dir / "link.csv"));
}

TEST(OutputFile, FifoWithAReaderIsWrittenInPlace) {
  const auto dir = scratch_dir();
  const auto fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);  // does not wait for a writer
  ASSERT_GE(reader, 0);
  std::string received;
  std::thread reading([&] { received = read_until_closed(reader, 5000); });
  {
    OutputFile f(fifo.string());
    EXPECT_TRUE(f.in_place());
    f.write(std::string_view("streamed bytes"));
    f.commit();
  }
  reading.join();
  ::close(reader);
  EXPECT_EQ(received, "streamed bytes");
  struct stat st {};
  ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "still the FIFO, not a regular file";
  EXPECT_FALSE(fs::exists(fifo.string() + ".partial"));
}

TEST(OutputFile, TerminalDeviceBehindASymlinkIsWrittenInPlace) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(::grantpt(master), 0);
  ASSERT_EQ(::unlockpt(master), 0);
  const auto dir = scratch_dir();
  fs::create_symlink(::ptsname(master), dir / "tty");
  {
    OutputFile f((dir / "tty").string());
    EXPECT_TRUE(f.in_place());
    f.write(std::string_view("pose"));
    f.commit();
  }
  pollfd p{master, POLLIN, 0};
  char buf[16] = {};
  const ssize_t n = ::poll(&p, 1, 2000) == 1 ? ::read(master, buf, sizeof buf) : 0;
  ::close(master);
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0), "pose");
  EXPECT_TRUE(is_link(dir / "tty"));
}

TEST(OutputFile, FullDeviceIsANoSpaceError) {
  const auto dir = scratch_dir();
  fs::create_symlink("/dev/full", dir / "full");
  const std::string e = error_of([&] {
    OutputFile f((dir / "full").string());
    f.write(std::string_view("bytes that do not fit"));
    f.commit();
  });
  EXPECT_NE(e.find("No space left"), std::string::npos) << e;
  EXPECT_TRUE(is_link(dir / "full"));
}

TEST(OutputFile, PipeWithoutAReaderIsABrokenPipeError) {
  std::signal(SIGPIPE, SIG_IGN);  // as main() does: EPIPE instead of death by signal
  const auto dir = scratch_dir();
  const auto fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);  // so that the writer can open
  ASSERT_GE(reader, 0);
  OutputFile f(fifo.string());
  ::close(reader);  // the reader goes away
  const std::string e = error_of([&] {
    f.write(std::string_view("lost"));
    f.commit();
  });
  EXPECT_NE(e.find("Broken pipe"), std::string::npos) << e;
}

TEST(OutputPaths, OutputThatIsAnInputIsRefused) {
  const auto dir = scratch_dir();
  write_text(dir / "log.vnb", "recording");
  fs::create_hard_link(dir / "log.vnb", dir / "other-name.vnb");
  const std::string e = error_of([&] {
    check_output_paths({(dir / "log.vnb").string()}, {{"--fe-out", ""}, {"--csv", (dir / "other-name.vnb").string()}});
  });
  EXPECT_NE(e.find("--csv"), std::string::npos) << e;
  EXPECT_NE(e.find("is the input"), std::string::npos) << e;
}

TEST(OutputPaths, TwoOutputsOnOneFileAreRefusedEvenBeforeItExists) {
  const auto dir = scratch_dir();
  const std::string e = error_of([&] {
    check_output_paths({}, {{"--fe-out", (dir / "a.out").string()}, {"--csv", (dir / "." / "a.out").string()}});
  });
  EXPECT_NE(e.find("same file"), std::string::npos) << e;
}

TEST(OutputPaths, DistinctFilesAndDevicesPass) {
  const auto dir = scratch_dir();
  write_text(dir / "log.vnb", "recording");
  EXPECT_NO_THROW(check_output_paths({(dir / "log.vnb").string()}, {{"--fe-out", (dir / "a.p1log").string()},
                                                                      {"--mip-out", "/dev/null"},
                                                                      {"--csv", "/dev/null"}}));
}

TEST(CommandOutputs, ReplayOutputOnTheInputIsRefusedAndTheInputKept) {
  const auto dir = scratch_dir();
  const fs::path demo = fs::path(NAVFUSE_SOURCE_DIR) / "data/demo/vn300.vnb";
  fs::copy_file(demo, dir / "mine.vnb");
  const auto r = run_cli({"replay", (dir / "mine.vnb").string(), "--csv", (dir / "mine.vnb").string(), "-q"});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.error.find("is the input"), std::string::npos) << r.error;
  EXPECT_EQ(fs::file_size(dir / "mine.vnb"), fs::file_size(demo));
}

TEST(CommandOutputs, DecodeOutputOnTheInputIsRefusedAndTheInputKept) {
  const auto dir = scratch_dir();
  const fs::path demo = fs::path(NAVFUSE_SOURCE_DIR) / "data/demo/vn300.vnb";
  fs::copy_file(demo, dir / "mine.vnb");
  fs::create_symlink("mine.vnb", dir / "link.vnb");
  const auto r = run_cli({"decode", (dir / "mine.vnb").string(), "-o", (dir / "link.vnb").string()});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.error.find("is the input"), std::string::npos) << r.error;
  EXPECT_EQ(fs::file_size(dir / "mine.vnb"), fs::file_size(demo));
}

}  // namespace
}  // namespace navfuse::apps
