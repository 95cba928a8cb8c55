// `navfuse run --configure-device` end to end through the real binary (issue 17): the
// installation geometry of the config reaches the device, is read back, and a device that
// refuses it or reads back something else ends the run with an error naming the setting.
//
//  - CV7 and FusionEngine: the device is another navfuse process emulating it on its --mip-out /
//    --fe-out TCP link (apps/run/mip_device_emulator.hpp, fe_device_emulator.hpp); that process
//    logs each lever arm it takes into its engine, which is where the test sees what arrived.
//  - VN-300: a pseudo-terminal the test answers as the ICD says a VN-300 does (a write is echoed,
//    a read answered with the register's values, §1.3), optionally with a wrong Reg 57.
//
// The configured vehicle has its IMU yawed +90 deg (sensor x = vehicle right): lever arms in the
// vehicle frame (1, 0.5, -1) and (1, -0.5, -1) are (0.5, -1, -1) and (-0.5, -1, -1) on the
// sensor's axes, the frame VN-300 and CV7 take them in; the wheel point (-1.5, 0, 0.3) is
// (0, 1.5, 0.3). FusionEngine takes vehicle-frame lever arms (FLU on the wire).
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <map>
#include <thread>

#include "frontends/vectornav/ascii_sentence.hpp"
#include "frontends/vectornav/commands.hpp"
#include "tests/integration/child_process.hpp"
#include "tests/integration/pty_device.hpp"
#include "tests/integration/test_paths.hpp"

namespace navfuse::test {
namespace {

namespace vn = frontends::vectornav;

constexpr int kTimeoutMs = 30000;
constexpr const char* kVehicle =
    "imu:\n  mounting_rpy_deg: [0, 0, 90]\n"
    "gnss:\n  lever_arm_m: [1.0, 0.5, -1.0]\n  secondary_lever_arm_m: [1.0, -0.5, -1.0]\n"
    "wheel:\n  lever_arm_m: [-1.5, 0, 0.3]\n";

// A navfuse process that is the "device": an input that never sends (UDP), its MIP and
// FusionEngine device links on TCP.
class EmulatedDevice {
 public:
  explicit EmulatedDevice(const std::filesystem::path& dir)
      : mip_port_(free_port(SOCK_STREAM)), fe_port_(free_port(SOCK_STREAM)) {
    const std::string config = write_file(dir / "device.yaml", "device: generic\n");
    process_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{navfuse_binary(), "run", "--config", config,
                                 "vn:udp-listen://127.0.0.1:" + std::to_string(free_port(SOCK_DGRAM)), "--mip-out",
                                 "tcp-listen://127.0.0.1:" + std::to_string(mip_port_), "--fe-out",
                                 "tcp-listen://127.0.0.1:" + std::to_string(fe_port_)},
        (dir / "device.log").string());
  }
  bool running() const { return process_->wait_for_output("running", kTimeoutMs); }
  std::string mip_uri() const { return "mip:tcp://127.0.0.1:" + std::to_string(mip_port_); }
  std::string fe_uri() const { return "fe:tcp://127.0.0.1:" + std::to_string(fe_port_); }
  const ChildProcess& process() const { return *process_; }

 private:
  std::uint16_t mip_port_, fe_port_;
  std::unique_ptr<ChildProcess> process_;
};

// The vector a log line "<prefix> (x, y, z)" gives; NaNs when there is no such line.
std::array<double, 3> logged_vector(const std::string& log, const std::string& prefix) {
  std::array<double, 3> v{NAN, NAN, NAN};
  const auto at = log.find(prefix + " (");
  if (at != std::string::npos) std::sscanf(log.c_str() + at + prefix.size(), " (%lf, %lf, %lf)", &v[0], &v[1], &v[2]);
  return v;
}

void expect_logged(const std::string& log, const std::string& prefix, const std::array<double, 3>& expected) {
  const auto v = logged_vector(log, prefix);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(v[i], expected[i], 1e-4) << prefix << "\n" << log;
}

class RunConfigureDeviceTest : public ScratchDirTest {
 protected:
  std::unique_ptr<ChildProcess> configure(const std::string& input, const std::string& config_text) {
    const std::string config = write_file(dir_ / "vehicle.yaml", config_text);
    return std::make_unique<ChildProcess>(
        std::vector<std::string>{navfuse_binary(), "run", "--config", config, input, "--configure-device", "--quiet"},
        (dir_ / "nav.log").string());
  }
  // The run verified its device, then ends on SIGTERM with 0.
  static void expect_verified_then_clean_exit(ChildProcess& nav, const std::string& settings) {
    ASSERT_TRUE(nav.wait_for_output(settings + " settings read back as written", kTimeoutMs)) << nav.output();
    nav.send(SIGTERM);
    EXPECT_EQ(nav.wait_exit(kTimeoutMs), std::optional<int>(0)) << nav.output();
  }
};

TEST_F(RunConfigureDeviceTest, Cv7GetsBothAntennasAndTheWheelPointInItsFrame) {
  EmulatedDevice device(dir_);
  ASSERT_TRUE(device.running()) << device.process().output();
  auto nav = configure(device.mip_uri(), std::string("device: cv7\n") + kVehicle);
  expect_verified_then_clean_exit(*nav, "3");
  // The device's filter thread takes the commands a moment after answering them.
  ASSERT_TRUE(device.process().wait_for_output("wheel lever arm set by command", kTimeoutMs));
  const std::string arrived = device.process().output();
  expect_logged(arrived, "GNSS lever arm of antenna 0 set by command to", {0.5, -1.0, -1.0});
  expect_logged(arrived, "GNSS lever arm of antenna 1 set by command to", {-0.5, -1.0, -1.0});
  expect_logged(arrived, "wheel lever arm set by command to", {0.0, 1.5, 0.3});
}

TEST_F(RunConfigureDeviceTest, FusionEngineDeviceGetsTheVehicleFrameLeverArms) {
  EmulatedDevice device(dir_);
  ASSERT_TRUE(device.running()) << device.process().output();
  auto nav = configure(device.fe_uri(), std::string("device: fusionengine\n") + kVehicle);
  expect_verified_then_clean_exit(*nav, "6");  // device, GNSS, GNSS aux lever arm; 3 message rates
  ASSERT_TRUE(device.process().wait_for_output("antenna 1 set by command", kTimeoutMs));
  const std::string arrived = device.process().output();
  expect_logged(arrived, "GNSS lever arm of antenna 0 set by command to", {1.0, 0.5, -1.0});
  expect_logged(arrived, "GNSS lever arm of antenna 1 set by command to", {1.0, -0.5, -1.0});
}

TEST_F(RunConfigureDeviceTest, ARefusedLeverArmEndsTheRunWithTheReason) {
  EmulatedDevice device(dir_);
  ASSERT_TRUE(device.running()) << device.process().output();
  // 12 m is beyond the CV7's documented 10 m (digest §6.9): the device NACKs "invalid parameter".
  auto nav = configure(device.mip_uri(), "device: cv7\ngnss:\n  lever_arm_m: [12.0, 0, 0]\n");
  const auto code = nav->wait_exit(kTimeoutMs);  // without a signal: the run stops by itself
  ASSERT_TRUE(code.has_value()) << nav->output();
  EXPECT_NE(*code, 0);
  EXPECT_NE(nav->output().find("device refused a set-up command: MIP NACK 3 for command (0x0D,0x54) (setting CV7 GNSS "
                               "antenna 1 offset (0x0D,0x54, device vehicle frame, m) to (12.0000, 0.0000, 0.0000))"),
            std::string::npos)
      << nav->output();
  EXPECT_EQ(device.process().output().find("set by command to (12"), std::string::npos);
}

// A VN-300 on a pty: echoes writes and answers reads with the register's last written values;
// `reg57_y_error_m` is added to Reg 57's y when read (a device that holds something else).
class FakeVn300 {
 public:
  FakeVn300(PtyDevice& pty, double reg57_y_error_m) : pty_(pty), error_(reg57_y_error_m) {
    thread_ = std::thread([this] { serve(); });
  }
  ~FakeVn300() {
    stop_ = true;
    thread_.join();
  }
  std::string received() const {
    std::lock_guard lock(mutex_);
    return received_;
  }

 private:
  void serve() {
    std::string pending;
    while (!stop_) {
      pollfd p{pty_.master(), POLLIN, 0};
      if (::poll(&p, 1, 20) <= 0) continue;
      char buf[1024];
      const ssize_t n = ::read(pty_.master(), buf, sizeof buf);
      if (n <= 0) continue;
      pending.append(buf, static_cast<std::size_t>(n));
      {
        std::lock_guard lock(mutex_);
        received_.append(buf, static_cast<std::size_t>(n));
      }
      for (std::size_t end; (end = pending.find("\r\n")) != std::string::npos; pending.erase(0, end + 2)) {
        answer(pending.substr(0, end));
      }
    }
  }
  void answer(const std::string& sentence) {
    const auto cmd = vn::cmd::parse_reply(sentence);
    if (!cmd) return;
    std::string reply = sentence + "\r\n";  // writes and other commands are echoed
    if (cmd->header == "VNWRG") registers_[cmd->register_id] = cmd->values;
    if (cmd->header == "VNRRG") {
      std::vector<std::string> values = registers_[cmd->register_id];
      if (cmd->register_id == 57 && values.size() == 3) values[1] = std::to_string(std::stod(values[1]) + error_);
      std::string body = "VNRRG," + std::to_string(cmd->register_id);
      for (const auto& v : values) body += "," + v;
      reply = vn::make_sentence(body);
    }
    pty_.write_all(reinterpret_cast<const std::uint8_t*>(reply.data()), reply.size());
  }

  PtyDevice& pty_;
  double error_;
  std::map<int, std::vector<std::string>> registers_;
  mutable std::mutex mutex_;
  std::string received_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

TEST_F(RunConfigureDeviceTest, Vn300GetsAntennaAAndTheBaselineInItsBodyFrame) {
  PtyDevice pty((dir_ / "ttyVN").string());
  FakeVn300 device(pty, 0.0);
  auto nav = configure("vn:serial:" + pty.link() + "?baud=921600", std::string("device: vn300\n") + kVehicle);
  expect_verified_then_clean_exit(*nav, "2");  // Reg 57, Reg 93
  const std::string got = device.received();
  EXPECT_EQ(got.find("$VNASY,0"), 0u) << got;  // output paused first
  EXPECT_NE(got.find("$VNWRG,75,"), std::string::npos) << got;  // binary output 1: IMU
  EXPECT_NE(got.find("$VNWRG,76,"), std::string::npos) << got;  // binary output 2: GNSS
  EXPECT_NE(got.find("$VNWRG,57,0.5,-1,-1*"), std::string::npos) << got;
  // Baseline B - A on the sensor axes: (-0.5, -1, -1) - (0.5, -1, -1) = (-1, 0, 0).
  EXPECT_NE(got.find("$VNWRG,93,-1,0,0,0.0254,0.0254,0.0254*"), std::string::npos) << got;
  EXPECT_NE(got.find("$VNRRG,57*"), std::string::npos) << got;
  pty.release_slave();
}

TEST_F(RunConfigureDeviceTest, AVn300ThatReadsBackAnotherOffsetEndsTheRun) {
  PtyDevice pty((dir_ / "ttyVN").string());
  FakeVn300 device(pty, 0.1);
  auto nav = configure("vn:serial:" + pty.link() + "?baud=921600", std::string("device: vn300\n") + kVehicle);
  const auto code = nav->wait_exit(kTimeoutMs);
  ASSERT_TRUE(code.has_value()) << nav->output();
  EXPECT_NE(*code, 0);
  const std::string out = nav->output();
  EXPECT_NE(out.find("device set-up not verified: VN-300 GNSS antenna A offset (Reg 57"), std::string::npos) << out;
  EXPECT_NE(out.find("sent (0.5000, -1.0000, -1.0000), read (0.5000, -0.9000, -1.0000)"), std::string::npos) << out;
  pty.release_slave();
}

}  // namespace
}  // namespace navfuse::test
