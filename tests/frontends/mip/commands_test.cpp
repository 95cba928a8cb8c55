// Commands: the CV7 setup sequence, reply parsing on the doc's own reply (L3941) and the
// CommandResponder answering as a CV7 would.
#include <gtest/gtest.h>

#include "frontends/mip/commands.hpp"
#include "frontends/mip/field_schema.hpp"
#include "frontends/mip/frame_record.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/responder.hpp"
#include "frontends/mip/writer.hpp"
#include "tests/frontends/mip/test_util.hpp"

namespace navfuse::frontends::mip {
namespace {

std::vector<ReplyEntry> reply_of(const std::vector<std::uint8_t>& reply) {
  std::vector<ReplyEntry> e;
  if (reply.size() < kWrapperSize) return e;
  EXPECT_TRUE(Framer::packet_valid(reply.data(), reply.size()));
  EXPECT_TRUE(parse_reply(std::span<const std::uint8_t>(reply).subspan(kHeaderSize, reply[kLengthOffset]), e));
  return e;
}

TEST(MipCommands, SetupSequenceStreamsWhatFusionNeeds) {
  SetupOptions o;
  o.imu_rate_hz = 200;   // 1000 / 200 = decimation 5 (L1831)
  o.filter_rate_hz = 10;  // decimation 100
  const auto seq = cv7_setup_sequence(o);
  ASSERT_EQ(seq.size(), 10u);  // idle, 4 formats, 4 stream enables, resume
  std::vector<FrameRecord> recs;
  for (const auto& p : seq) {
    Framer f;
    f.feed(p, [&](const PacketView& v) {
      recs.emplace_back();
      build_frame_record(v, recs.back());
    });
    ASSERT_EQ(f.counters().frames, 1u);
  }
  EXPECT_EQ(seq.front(), test::hex("756501020202E1C7"));  // idle first (§11.4)
  EXPECT_EQ(seq.back(), test::hex("756501020206E5CB"));   // resume last
  // 0x80: D3, D5, delta theta, delta velocity at decimation 5.
  EXPECT_EQ(*test::field(recs[1], "message_format.desc_set"), 0x80);
  EXPECT_EQ(*test::field(recs[1], "message_format.descriptor[2]"), 0x07);
  EXPECT_EQ(*test::field(recs[1], "message_format.descriptor[3]"), 0x08);
  EXPECT_EQ(*test::field(recs[1], "message_format.decimation[3]"), 5);
  EXPECT_EQ(*test::field(recs[2], "message_format.desc_set"), 0x91);
  EXPECT_EQ(*test::field(recs[2], "message_format.decimation[0]"), 1);
  EXPECT_EQ(*test::field(recs[3], "message_format.desc_set"), 0x92);
  EXPECT_EQ(*test::field(recs[4], "message_format.desc_set"), 0x82);
  EXPECT_EQ(*test::field(recs[4], "message_format.decimation[0]"), 100);
  for (int i = 5; i < 9; ++i) EXPECT_EQ(*test::field(recs[static_cast<std::size_t>(i)], "data_stream_control.enable"), 1);
}

TEST(MipCommands, ParseReplyOfThreePpsCommands) {
  // L3941: three ACKs, the READ's response 0xA8 source 1 after the third.
  const auto pkt = test::hex("75650C0F 04F12800 04F12800 04F12800 03A801 F8D9");
  const auto e = reply_of(pkt);
  ASSERT_EQ(e.size(), 3u);
  for (const auto& x : e) EXPECT_EQ(x.cmd_desc, 0x28);
  EXPECT_FALSE(e[0].response_desc.has_value());
  ASSERT_TRUE(e[2].response_desc.has_value());
  EXPECT_EQ(*e[2].response_desc, 0xA8);
  EXPECT_EQ(e[2].response_data, std::vector<std::uint8_t>{0x01});
}

TEST(MipCommands, ResponderAnswersLikeACv7) {
  CommandResponder dev;
  std::vector<std::uint8_t> reply;
  std::vector<Measurement> aiding;
  // Ping -> exactly the doc's ACK packet (L3913).
  dev.handle_packet(test::hex("75650102 0201 E0C6"), reply, aiding);
  EXPECT_EQ(reply, test::hex("75 65 01 04 04 F1 01 00 D5 6A"));
  // Base rate of 0x80 -> exactly the doc's reply (L3921).
  dev.handle_packet(test::hex("75650C03 030E80 7A7E"), reply, aiding);
  EXPECT_EQ(reply, test::hex("75650C09 04F10E00 058E8003E8 F058"));
  // PPS write then read back; DEFAULT, SAVE, READ in one packet answered in order.
  dev.handle_packet(test::hex("75650c04 04280104 1b55"), reply, aiding);
  EXPECT_EQ(reply, test::hex("75650C04 04F12800 07FA"));  // L3929
  dev.handle_packet(*build_command_packet(Command{0x0C, 0x28, {std::uint64_t{2}}}), reply, aiding);
  auto e = reply_of(reply);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].response_data, std::vector<std::uint8_t>{0x04});
  // Message format write for 0x82 then read: the same descriptors and decimations come back.
  const DescriptorRate f[] = {{0xD3, 10}, {0x01, 10}, {0x05, 20}};
  dev.handle_packet(*build_command_packet(message_format(0x82, f)), reply, aiding);
  EXPECT_EQ(reply_of(reply).at(0).code, ReplyCode::kAck);
  dev.handle_packet(*build_command_packet(Command{0x0C, 0x0F, {std::uint64_t{2}, std::uint64_t{0x82}}}), reply, aiding);
  e = reply_of(reply);
  ASSERT_EQ(e.size(), 1u);
  ASSERT_TRUE(e[0].response_desc.has_value());
  EXPECT_EQ(*e[0].response_desc, 0x8F);
  EXPECT_EQ(e[0].response_data, (std::vector<std::uint8_t>{0x82, 3, 0xD3, 0, 10, 0x01, 0, 10, 0x05, 0, 20}));
  // Device info: model number in the 0x81 response.
  dev.handle_packet(*build_command_packet(get_device_info()), reply, aiding);
  e = reply_of(reply);
  ASSERT_EQ(e.size(), 1u);
  ASSERT_EQ(e[0].response_data.size(), 82u);  // base_device_info (digest §2.4)
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(e[0].response_data.data() + 18), 16).substr(0, 16),
            std::string("3DM-CV7-GNSS/INS"));
  // Idle / resume and stream control.
  dev.handle_packet(*build_command_packet(set_idle()), reply, aiding);
  EXPECT_TRUE(dev.idle());
  dev.handle_packet(*build_command_packet(stream_enable(0x80, false)), reply, aiding);
  EXPECT_FALSE(dev.stream_enabled(0x80));
  EXPECT_TRUE(dev.stream_enabled(0x82));
  dev.handle_packet(*build_command_packet(resume()), reply, aiding);
  EXPECT_FALSE(dev.idle());
  // Unknown command, unknown set, bad checksum.
  dev.handle_packet(make_packet(0x01, 0x55, {}), reply, aiding);
  EXPECT_EQ(reply_of(reply).at(0).code, ReplyCode::kUnknownCommand);
  dev.handle_packet(make_packet(0x22, 0x01, {}), reply, aiding);
  EXPECT_EQ(reply_of(reply).at(0).code, ReplyCode::kUnknownDescriptorSet);
  auto bad = test::hex("75650102 0201 E0C6");
  bad.back() = 0;
  dev.handle_packet(bad, reply, aiding);
  EXPECT_EQ(reply_of(reply).at(0).code, ReplyCode::kBadChecksum);
  // Aiding is routed to the aiding handler.
  dev.handle_packet(test::hex("7565131E1E0101010101BEA3D70A3DE147AEBF23D70A00000000000000000000000046A1"), reply, aiding);
  EXPECT_EQ(reply_of(reply).at(0).code, ReplyCode::kAck);
  EXPECT_TRUE(dev.aiding_handler().frame(1).configured);
  EXPECT_NEAR(dev.aiding_handler().frame(1).translation_m.x(), -0.32, 1e-6);
}

// The set-up's reply check (FrontendInfo::find_refusal): ACKs pass, the first NACK is named with
// its code and the command it answers (ACK/NACK field 0xF1: echoed descriptor, code; L3852).
TEST(MipCommands, FindRefusalNamesTheFirstNack) {
  std::vector<std::uint8_t> bytes = test::hex("75 65 01 04 04 F1 01 00 D5 6A");  // Ping ACK (L3913)
  EXPECT_EQ(find_refusal(bytes), "");
  bytes.push_back(0x00);  // noise between packets
  const std::uint8_t unknown_command[] = {0x55, 0x01};
  const std::vector<std::uint8_t> nack = make_packet(0x01, 0xF1, unknown_command);
  bytes.insert(bytes.end(), nack.begin(), nack.end());
  const std::uint8_t bad_parameter[] = {0x0F, 0x03};
  const std::vector<std::uint8_t> second = make_packet(0x0C, 0xF1, bad_parameter);
  bytes.insert(bytes.end(), second.begin(), second.end());
  EXPECT_EQ(find_refusal(bytes), "MIP NACK 1 for command (0x01,0x55)");
}

}  // namespace
}  // namespace navfuse::frontends::mip
