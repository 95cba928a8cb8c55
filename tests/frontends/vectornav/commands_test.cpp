// Command encoding against the ICD's command examples (digest §2.4, §6), reply parsing, and the
// fusion setup sequence read back through the reply parser.
#include <gtest/gtest.h>

#include "core/bytes/checks.hpp"
#include "frontends/vectornav/ascii_registers.hpp"
#include "frontends/vectornav/commands.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::vectornav::cmd {
namespace {

TEST(VnCommands, SimpleCommandsMatchTheIcdExamples) {
  EXPECT_EQ(read_register(5), "$VNRRG,5*46\r\n");       // L195
  EXPECT_EQ(read_register(11), "$VNRRG,11*73\r\n");     // L130
  EXPECT_EQ(write_settings(), "$VNWNV*57\r\n");          // L243
  EXPECT_EQ(restore_factory_settings(), "$VNRFS*5F\r\n");  // L265
  EXPECT_EQ(reset(), "$VNRST*4D\r\n");                   // L287
  EXPECT_EQ(async_output(true), "$VNASY,1*4E\r\n");      // L476
  const std::vector<std::string> baud{"921600"};
  EXPECT_EQ(write_register(5, baud), "$VNWRG,5,921600*63\r\n");  // errata A4: L217's correct XOR
  EXPECT_EQ(read_register(5, AsciiChecksum::kCrc16), "$VNRRG,5*D5A3\r\n");  // digest §2.3
  EXPECT_EQ(write_settings(AsciiChecksum::kCrc16), "$VNWNV*DBDF\r\n");
}

TEST(VnCommands, BinaryOutputConfigurationMatchesA11AndB1) {
  // A.1.1 (L5225, typo VNRG for VNWRG): Common{TimeStartup, Ypr} + Attitude{YprU}, divisor 10.
  BinaryOutputConfig c;
  c.async_mode = 1;
  c.rate_divisor = 10;
  c.header.set(kSlotCommon, common_type::kTimeStartup);
  c.header.set(kSlotCommon, common_type::kYpr);
  c.header.set(kSlotAttitude, attitude_type::kYprU);
  EXPECT_EQ(write_binary_output(1, c), "$VNWRG,75,1,10,11,0009,0100*60\r\n");
  // B.1.1 example (L5378) under raw numbering: Attitude{YprU} + Gnss3{TimeUtc, GnssStatus}.
  BinaryOutputConfig e;
  e.async_mode = 1;
  e.rate_divisor = 10;
  e.header.set(kSlotAttitude, attitude_type::kYprU);
  e.header.set(kSlotGnss3, gnss_type::kTimeUtc);
  e.header.set(kSlotGnss3, gnss_type::kStatus);
  EXPECT_EQ(write_binary_output(1, e), "$VNWRG,75,1,10,90,10,0100,8001,0002*6A\r\n");
  // Read back.
  const auto reply = parse_reply("$VNWRG,75,1,10,90,10,0100,8001,0002*6A");
  ASSERT_TRUE(reply);
  const auto back = parse_binary_output(*reply);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->rate_divisor, 10);
  EXPECT_EQ(back->header.types, e.header.types);
  // An empty configuration (L2975).
  const auto off = parse_reply("$VNRRG,75,0,0,00*5D");
  ASSERT_TRUE(off);
  const auto off_cfg = parse_binary_output(*off);
  ASSERT_TRUE(off_cfg);
  EXPECT_EQ(off_cfg->header.groups, 0u);
}

TEST(VnCommands, RegisterWritesReadBackThroughTheReplyParser) {
  const Eigen::Matrix3d rfr = (Eigen::Matrix3d() << 1, 0, 0, 0, -1, 0, 0, 0, -1).finished();
  EXPECT_EQ(write_reference_frame_rotation(rfr), "$VNWRG,26,1,0,0,0,-1,0,0,0,-1*6F\r\n");  // L3476
  EXPECT_EQ(write_antenna_offset(Antenna::kExternal, {1, 1, 1}), "$VNWRG,157,1,1,1*58\r\n");  // L4061
  EXPECT_EQ(write_velocity_aiding({1, 2, 3}), "$VNWRG,50,1,2,3*6F\r\n");  // L3717
  const auto r26 = parse_reply(write_reference_frame_rotation(rfr));
  ASSERT_TRUE(r26);
  EXPECT_EQ(*parse_reference_frame_rotation(*r26), rfr);
  const auto r57 = parse_reply(write_antenna_offset(Antenna::kInternalA, {0.75, -0.5, 0.125}));
  ASSERT_TRUE(r57);
  EXPECT_EQ(*parse_vector3(*r57, reg::kGnssAntennaA), Eigen::Vector3d(0.75, -0.5, 0.125));
  const auto r93 = parse_reply("$VNRRG,93,+01.000,+00.000,+00.000,00.0254,00.0254,00.0254*60");  // L4258
  ASSERT_TRUE(r93);
  const auto baseline = parse_compass_baseline(*r93);
  ASSERT_TRUE(baseline);
  EXPECT_EQ(baseline->baseline_m, Eigen::Vector3d(1, 0, 0));
  EXPECT_DOUBLE_EQ(baseline->uncertainty_m.z(), 0.0254);
  const auto r67 = parse_reply("$VNRRG,67,3,1,1,0*71");  // L4083
  ASSERT_TRUE(r67);
  const auto ins = parse_ins_basic_config(*r67);
  ASSERT_TRUE(ins);
  EXPECT_EQ(ins->scenario, 3);
  EXPECT_TRUE(ins->ahrs_aiding && ins->estimate_baseline);
  EXPECT_EQ(parse_reply(write_ins_basic_config(*ins))->values, r67->values);
  const auto r51 = parse_reply("$VNRRG,51,1,0.1,0.01*5A");  // L3741
  ASSERT_TRUE(r51);
  const auto vac = parse_velocity_aiding_control(*r51);
  ASSERT_TRUE(vac);
  EXPECT_TRUE(vac->enable);
  EXPECT_FLOAT_EQ(vac->uncertainty_tuning, 0.1f);
  // L3741's verified read *5A with RRG -> WRG: XOR changes by 'R' ^ 'W' = 0x05, so *5F.
  EXPECT_EQ(write_velocity_aiding_control(*vac), "$VNWRG,51,1,0.1,0.01*5F\r\n");
  EXPECT_EQ(parse_reply(write_velocity_aiding_control(*vac))->values, r51->values);
}

TEST(VnCommands, RepliesErrorsAndBadChecksums) {
  const auto err = parse_reply("$VNERR,0C*02");
  ASSERT_TRUE(err);
  EXPECT_EQ(err->kind, Reply::Kind::kError);
  EXPECT_EQ(err->error_code, 0x0Cu);
  const auto e72 = parse_reply("$VNERR,03*72\r\n");  // L2882 without the typeset space
  ASSERT_TRUE(e72);
  EXPECT_EQ(e72->error_code, 3u);
  EXPECT_FALSE(parse_reply("$VNWRG,5,921600*46"));  // L217: wrong checksum (errata A4)
  const auto echo = parse_reply("$VNWNV*57");
  ASSERT_TRUE(echo);
  EXPECT_EQ(echo->kind, Reply::Kind::kEcho);
  const auto padded = parse_reply("$VNRRG,05,115200*5D");  // errata A24: zero-padded id
  ASSERT_TRUE(padded);
  EXPECT_EQ(padded->register_id, 5);
  EXPECT_EQ(padded->values, std::vector<std::string>{"115200"});
}

TEST(VnCommands, FusionSetupSequence) {
  FusionSetup setup;
  setup.antenna_a_offset_m = Eigen::Vector3d(0.75, -0.5, 0);
  const auto seq = fusion_setup_commands(setup);
  ASSERT_GE(seq.size(), 6u);
  EXPECT_EQ(seq.front(), "$VNASY,0*4F\r\n");
  EXPECT_EQ(seq.back(), "$VNASY,1*4E\r\n");
  bool imu = false, gnss = false;
  for (const auto& s : seq) {
    const auto r = parse_reply(s);
    ASSERT_TRUE(r) << s;  // every command carries a valid checksum
    if (r->kind != Reply::Kind::kRegister) continue;
    if (r->register_id == reg::kBinaryOutput1) {
      const auto c = parse_binary_output(*r);
      ASSERT_TRUE(c);
      EXPECT_EQ(kImuRateHz / c->rate_divisor, 200);  // errata A10: 400 Hz base
      EXPECT_TRUE(c->header.has(kSlotImu, imu_type::kDeltaTheta));
      EXPECT_TRUE(c->header.has(kSlotIns, ins_type::kInsStatus));
      EXPECT_TRUE(c->header.has(kSlotTime, time_type::kTimeGps));
      imu = true;
    }
    if (r->register_id == reg::kBinaryOutput2) {
      const auto c = parse_binary_output(*r);
      ASSERT_TRUE(c);
      EXPECT_EQ(kImuRateHz / c->rate_divisor, 5);
      EXPECT_TRUE(c->header.has(kSlotGnss1, gnss_type::kPosLla));
      EXPECT_TRUE(c->header.has(kSlotGnss2, gnss_type::kVelNed));
      gnss = true;
    }
  }
  EXPECT_TRUE(imu && gnss);
  // The configured output 1 message is 159 bytes (documented bandwidth).
  std::size_t payload = 0;
  const BinaryHeader h = fusion_imu_output(setup).header;
  std::vector<std::uint8_t> wire;
  append_header(h, wire);
  ASSERT_EQ(measure_payload(h, {}, 1000, payload), ParseStatus::kOk);
  EXPECT_EQ(1 + wire.size() + payload + kCrcBytes, 159u);
}

// The set-up's reply check (FrontendInfo::find_refusal): the first error line, without its end.
TEST(VnCommands, FindRefusalReturnsTheErrorLine) {
  const std::string ok = "$VNWRG,51,1,0.1,0.01*5F\r\n";  // L3741 as a write reply
  EXPECT_EQ(find_refusal(bytes::as_bytes(ok)), "");
  const std::string refused = ok + "$VNERR,03*72\r\n$VNERR,0C*02\r\n";
  EXPECT_EQ(find_refusal(bytes::as_bytes(refused)), "$VNERR,03*72");
}

}  // namespace
}  // namespace navfuse::frontends::vectornav::cmd
