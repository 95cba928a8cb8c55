// `navfuse run --record DIR` on live links, then `navfuse replay --recording DIR`: a simulated
// VN-300 on a pseudo-terminal and FusionEngine vehicle speeds on TCP, played at 15x real time;
// the recording holds exactly the bytes the test wrote, and its replay writes the same
// FusionEngine and MIP output files as the live run, byte for byte.
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/integration/child_process.hpp"
#include "tests/integration/pty_device.hpp"
#include "tests/integration/sim_log.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

constexpr int kTimeoutMs = 15000;
constexpr double kSpeedUp = 15.0;

bool write_fd(int fd, const std::uint8_t* data, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// Plays both logs, merged by delivery time, `kSpeedUp` times faster than real time.
bool play(PtyDevice& vn, const SimLog& vn_log, int tcp_fd, const SimLog& fe_log) {
  const auto wall_start = std::chrono::steady_clock::now();
  const std::int64_t start_ns = std::min(vn_log.start_ns, fe_log.start_ns);
  std::size_t i = 0, j = 0, vn_begin = 0, fe_begin = 0;
  while (i < vn_log.pieces.size() || j < fe_log.pieces.size()) {
    const bool vn_next = j == fe_log.pieces.size() ||
                         (i < vn_log.pieces.size() && vn_log.pieces[i].delivery_ns <= fe_log.pieces[j].delivery_ns);
    const SimLog::Piece& piece = vn_next ? vn_log.pieces[i] : fe_log.pieces[j];
    std::this_thread::sleep_until(wall_start + std::chrono::nanoseconds(static_cast<std::int64_t>(
                                                   static_cast<double>(piece.delivery_ns - start_ns) / kSpeedUp)));
    if (vn_next) {
      if (!vn.write_all(vn_log.bytes.data() + vn_begin, piece.end - vn_begin)) return false;
      vn_begin = piece.end;
      ++i;
    } else {
      if (!write_fd(tcp_fd, fe_log.bytes.data() + fe_begin, piece.end - fe_begin)) return false;
      fe_begin = piece.end;
      ++j;
    }
  }
  return true;
}

std::string read_binary(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The bytes the index of a recorded input says were read (sum of its R lines).
std::uint64_t indexed_bytes(const std::filesystem::path& index) {
  std::ifstream in(index);
  std::uint64_t total = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] != 'R') continue;
    std::istringstream ss(line.substr(1));
    std::int64_t seq = 0, mono = 0, utc = 0;
    std::uint64_t length = 0;
    ss >> seq >> mono >> utc >> length;
    total += length;
  }
  return total;
}

using RunRecordTest = ScratchDirTest;

TEST_F(RunRecordTest, RecordingReplaysToTheLiveRunsOutputsByteForByte) {
  const SimLog vn_log = make_sim_log("drive_short", "vn", 60.0);
  const SimLog fe_log = make_sim_log("drive_short", "fe", 60.0, MeasurementKind::kVehicleSpeed);
  ASSERT_GT(vn_log.pieces.size(), 1000u);
  ASSERT_GT(fe_log.pieces.size(), 500u);
  const std::string config = write_file(dir_ / "vn300.yaml", "device: vn300\noutput:\n  rate_hz: 50\n");
  const std::uint16_t tcp_port = free_port(SOCK_STREAM);
  const auto rec = dir_ / "rec";
  const auto live_fe = dir_ / "live.p1log", live_mip = dir_ / "live.mip";
  const auto live_summary = dir_ / "live.json";

  PtyDevice device((dir_ / "ttyVN").string());
  // The VN-300's format is detected from its bytes; the speeds' format is given.
  ChildProcess nav({navfuse_binary(), "run", "--config", config, "--in", "serial:" + device.link() + "?baud=921600",
                    "--in", "fe:tcp-listen://127.0.0.1:" + std::to_string(tcp_port), "--fe-out",
                    "file:" + live_fe.string(), "--mip-out", "file:" + live_mip.string(), "--record", rec.string(),
                    "--summary-json", live_summary.string()},
                   (dir_ / "nav.log").string());
  ASSERT_TRUE(nav.wait_for_output("running", kTimeoutMs)) << nav.output();
  device.release_slave();
  const io::UniqueFd speeds = connect_loopback(tcp_port, kTimeoutMs);
  ASSERT_TRUE(static_cast<bool>(speeds));
  ASSERT_TRUE(play(device, vn_log, speeds.get(), fe_log));
  // Let the last bytes reach the process, then stop it as an operator would.
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  nav.send(SIGTERM);
  const auto code = nav.wait_exit(kTimeoutMs);
  ASSERT_TRUE(code.has_value());
  ASSERT_EQ(*code, 0) << nav.output();

  // The recording holds exactly what was sent, and its index accounts for every byte.
  const std::string vn_sent(vn_log.bytes.begin(), vn_log.bytes.end());
  const std::string fe_sent(fe_log.bytes.begin(), fe_log.bytes.end());
  EXPECT_TRUE(read_binary(rec / "in0.raw") == vn_sent);
  EXPECT_TRUE(read_binary(rec / "in1.raw") == fe_sent);
  EXPECT_EQ(indexed_bytes(rec / "in0.idx"), vn_sent.size());
  EXPECT_EQ(indexed_bytes(rec / "in1.idx"), fe_sent.size());

  // Nothing was lost live (a dropped measurement could not be replayed), and speeds were fused.
  const auto live = nlohmann::json::parse(read_text_file(live_summary.string()));
  EXPECT_GT(live["measurements"]["vehicle_speed"]["used"].get<int>(), 500) << live.dump();
  EXPECT_GT(live["measurements"]["imu"]["used"].get<int>(), 5000) << live.dump();

  const auto replay_fe = dir_ / "replay.p1log", replay_mip = dir_ / "replay.mip";
  const RunResult replay = run_to_exit({navfuse_binary(), "replay", "--recording", rec.string(), "--fe-out",
                                        replay_fe.string(), "--mip-out", replay_mip.string(), "--quiet"},
                                       (dir_ / "replay.log").string(), kTimeoutMs);
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  const std::string fe_live = read_binary(live_fe), fe_replayed = read_binary(replay_fe);
  const std::string mip_live = read_binary(live_mip), mip_replayed = read_binary(replay_mip);
  EXPECT_GT(fe_live.size(), 100'000u);
  EXPECT_EQ(fe_live.size(), fe_replayed.size());
  EXPECT_TRUE(fe_live == fe_replayed) << "FusionEngine outputs differ";
  EXPECT_EQ(mip_live.size(), mip_replayed.size());
  EXPECT_TRUE(mip_live == mip_replayed) << "MIP outputs differ";
}

TEST_F(RunRecordTest, RefusesADirectoryThatHoldsARecording) {
  const std::string config = write_file(dir_ / "vn300.yaml", "device: vn300\n");
  const SimLog log = make_sim_log("drive_short", "vn", 2.0);
  const std::string input = (dir_ / "in.vnb").string();
  std::ofstream(input, std::ios::binary).write(reinterpret_cast<const char*>(log.bytes.data()),
                                               static_cast<std::streamsize>(log.bytes.size()));
  const auto rec = (dir_ / "rec").string();
  const RunResult first = run_to_exit({navfuse_binary(), "run", "--config", config, "--in", input, "--record", rec,
                                       "--quiet"},
                                      (dir_ / "first.log").string(), kTimeoutMs);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const RunResult second = run_to_exit({navfuse_binary(), "run", "--config", config, "--in", input, "--record", rec,
                                        "--quiet"},
                                       (dir_ / "second.log").string(), kTimeoutMs);
  EXPECT_EQ(second.exit_code, 1) << second.output;
  EXPECT_NE(second.output.find("already holds a recording"), std::string::npos) << second.output;
}

}  // namespace
}  // namespace navfuse::test
