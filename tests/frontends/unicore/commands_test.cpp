// Command encoders against the computed checksums of digest §10.2 (XOR of L164 over the printed
// examples), and the reply parser.
#include <gtest/gtest.h>

#include "core/bytes/checks.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/unicore/commands.hpp"
#include "frontends/unicore/commands_reply.hpp"

namespace navfuse::frontends::unicore {
namespace {

std::string line(const char* s) { return std::string(s) + "\r\n"; }

TEST(UnicoreCommands, QueriesUseTheTrailingCommaForm) {
  // L168: a parameterless command with a checksum is "NAME,*HH".
  EXPECT_EQ(encode_pdtinfo_query(), line("$PDTINFO,*62"));  // the spec's own example, L170
  EXPECT_EQ(encode(CfgTpCommand{}), line("$CFGTP,*6A"));
  EXPECT_EQ(encode(CfgNmeaCommand{}), line("$CFGNMEA,*69"));
  EXPECT_EQ(encode(CfgSysCommand{}), line("$CFGSYS,*37"));
  EXPECT_EQ(encode_cfgsave(), line("$CFGSAVE,*6F"));
  EXPECT_EQ(encode_cfgclr(), line("$CFGCLR,*33"));
  EXPECT_EQ(encode(CfgCwoutCommand{}), line("$CFGCWOUT,*34"));
  EXPECT_EQ(encode(CfgInsCommand{}), line("$CFGINS,*3A"));
  EXPECT_EQ(encode(CfgRotatCommand{}), line("$CFGROTAT,*32"));
  EXPECT_EQ(encode(CfgGeoidCommand{}), line("$CFGGEOID,*2E"));
  EXPECT_EQ(encode(CfgOdoFwdCommand{}), line("$CFGODOFWD,*7F"));
  EXPECT_EQ(encode(CfgCogCommand{}), line("$CFGCOG,*25"));
  EXPECT_EQ(encode_aidinfo_query(), line("$AIDINFO,*6E"));
  EXPECT_EQ(encode(CfgAttCommand{}), line("$CFGATT,*2F"));
}

TEST(UnicoreCommands, SpecExamplesEncodeToComputedChecksums) {
  EXPECT_EQ(encode(ResetCommand{ResetType::kSoftware, kClearWarmStart}), line("$RESET,0,h01*0C"));
  EXPECT_EQ(encode(CfgPrtCommand{1, {}, {}, {}}), line("$CFGPRT,1*09"));
  EXPECT_EQ(encode(CfgPrtCommand{1, 115200, 1, 3}), line("$CFGPRT,1,h0,115200,1,3*54"));
  EXPECT_EQ(encode(CfgMsgCommand{kMsgGll, {}}), line("$CFGMSG,0,1*1A"));
  EXPECT_EQ(encode(CfgMsgCommand{kMsgGll, true}), line("$CFGMSG,0,1,1*07"));
  EXPECT_EQ(encode(CfgTpCommand{1000000, 500000, 1, 0, 800, 0}), line("$CFGTP,1000000,500000,1,0,800,0*7B"));
  EXPECT_EQ(encode(CfgNmeaCommand{kNmeaVersion41, 1}), line("$CFGNMEA,h51,1*18"));
  EXPECT_EQ(encode(CfgSysCommand{0x11}), line("$CFGSYS,H11*7F"));
  EXPECT_EQ(encode(CfgCwoutCommand{true}), line("$CFGCWOUT,1*05"));
  EXPECT_EQ(encode(CfgInsCommand{1, 1, 1, 4}), line("$CFGINS,1,1,1,4*13"));
  EXPECT_EQ(encode(CfgRotatCommand{0.0, 0.0, 0.0, 2}), line("$CFGROTAT,0,0,0,2*1C"));
  EXPECT_EQ(encode(CfgGeoidCommand{0}), line("$CFGGEOID,0*1E"));
  EXPECT_EQ(encode(CfgOdoFwdCommand{1}), line("$CFGODOFWD,1*4E"));
  EXPECT_EQ(encode(CfgCogCommand{0}), line("$CFGCOG,0*15"));
  EXPECT_EQ(encode(AidTimeCommand{2018, 4, 9, 17, 41, 36, 200}), line("$AIDTIME,2018,4,9,17,41,36,200*47"));
  EXPECT_EQ(encode(AidPosCommand{40.0 + 2.229934 / 60.0, 116.0 + 18.096855 / 60.0, 37.254}),
            line("$AIDPOS,4002.229934,N,11618.096855,E,37.254*07"));
  EXPECT_EQ(encode(CfgAttCommand{1}), line("$CFGATT,1*1E"));
  EXPECT_EQ(encode_lsf_query(0), line("$LSF,0*45"));
}

TEST(UnicoreCommands, ChecksumIsTheXorOfTheBody) {
  // Independent of the expected strings above: recompute the XOR of every command produced.
  for (const std::string& s : fusion_setup_commands(true)) {
    ASSERT_GE(s.size(), 6u);
    EXPECT_EQ(s.substr(s.size() - 2), "\r\n");
    const std::size_t star = s.rfind('*');
    ASSERT_NE(star, std::string::npos);
    const unsigned printed = std::stoul(s.substr(star + 1, 2), nullptr, 16);
    EXPECT_EQ(printed, bytes::nmea_xor(std::string_view(s).substr(1, star - 1))) << s;
  }
}

TEST(UnicoreCommands, FusionSetupEnablesTheFusionOutputs) {
  const auto cmds = fusion_setup_commands(false);
  const auto has = [&](const char* s) {
    for (const auto& c : cmds) {
      if (c.rfind(s, 0) == 0) return true;
    }
    return false;
  };
  EXPECT_TRUE(has("$CFGMSG,4,0,1*"));  // GYOACC (L367)
  EXPECT_TRUE(has("$CFGMSG,1,0,1*"));  // NAVPOS
  EXPECT_TRUE(has("$CFGMSG,1,1,1*"));  // NAVVEL
  EXPECT_TRUE(has("$CFGMSG,4,2,1*"));  // NAVATT
  EXPECT_TRUE(has("$CFGMSG,1,3,1*"));  // NAVACC
  EXPECT_TRUE(has("$CFGMSG,1,2,1*"));  // NAVTIME
  EXPECT_TRUE(has("$CFGATT,10*"));
  EXPECT_FALSE(has("$CFGSAVE"));
  EXPECT_EQ(fusion_setup_commands(true).back(), encode_cfgsave());
}

TEST(UnicoreCommands, OutOfRangeValuesAreNotEncoded) {
  EXPECT_EQ(encode(AidTimeCommand{2018, 13, 9, 17, 41, 36, 200}), "");
  EXPECT_EQ(encode(CfgTpCommand{{}, {}, {}, 40000, {}, {}}), "");
  EXPECT_EQ(encode(AidPosCommand{91.0, 0.0, 0.0}), "");
  // Negative mounting angles wrap into 0..36000 hundredths of a degree.
  EXPECT_EQ(encode(CfgRotatCommand{-90.0, 0.0, 1.5, 0}), encode_command("CFGROTAT", {"27000", "0", "150", "0"}));
}

TEST(UnicoreCommands, AidTimeFromGpsTime) {
  // 2018-04-09 17:41:36.200 UTC with 18 leap seconds.
  const auto gps = time::gps_ns_from_utc({2018, 4, 9, 17, 41, 36.2});
  ASSERT_TRUE(gps);
  EXPECT_EQ(encode(aid_time_from_gps_ns(*gps)), line("$AIDTIME,2018,4,9,17,41,36,200*47"));
}

TEST(UnicoreReplies, OkFailEchoAndReports) {
  auto r = parse_reply_line("$OK*04\r\n");  // digest §10.2
  ASSERT_TRUE(r);
  EXPECT_EQ(r->kind, ReplyKind::kOk);
  r = parse_reply_line("$OK");  // printed without checksum (L267)
  ASSERT_TRUE(r);
  EXPECT_EQ(r->kind, ReplyKind::kOk);
  r = parse_reply_line("$FAIL,1*1F");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->kind, ReplyKind::kFail);
  EXPECT_EQ(*r->fail_code, static_cast<std::uint32_t>(FailCode::kChecksum));
  r = parse_reply_line("$FAIL,0");
  ASSERT_TRUE(r);
  EXPECT_EQ(*r->fail_code, 0u);
  EXPECT_FALSE(parse_reply_line("$FAIL,0*1F"));  // wrong checksum (right one is 1E)
  r = parse_reply_line("#CFGPRT,1,h0,115200,3,35");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->kind, ReplyKind::kEcho);
  EXPECT_EQ(r->fields[3], "115200");
  r = parse_reply_line("$cfgins,1,1,1,4");  // case-insensitive (L154)
  ASSERT_TRUE(r);
  EXPECT_EQ(r->kind, ReplyKind::kReport);
  EXPECT_EQ(r->fields[4], "4");
  r = parse_reply_line("$PDTINFO,UM220,G1B1,V4.1,R3.0Build13260,080101000001,000101114303845*35");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->kind, ReplyKind::kReport);
  EXPECT_EQ(r->fields[4], "R3.0Build13260");
  EXPECT_FALSE(parse_reply_line("$GPGGA,060845.00,4004.74005,N,11614.19613,E,1,10,0.85,53.5,M,,M,,*7B"));
}

TEST(UnicoreReplies, ReaderFindsRepliesInAStream) {
  ReplyReader reader;
  std::vector<ReplyKind> kinds;
  const std::string stream = "junk$OK*04\r\n$SNRSTAT,3,0,0,2*5C\r\n$FAIL,0*1E\r\n$CFGINS,1,1,1,4*13\r\n";
  for (char c : stream) {  // one byte at a time
    reader.feed(bytes::as_bytes(std::string_view(&c, 1)), [&](const Reply& r) { kinds.push_back(r.kind); });
  }
  EXPECT_EQ(kinds, (std::vector<ReplyKind>{ReplyKind::kOk, ReplyKind::kFail, ReplyKind::kReport}));
  EXPECT_EQ(reader.counters().frames, 4u);
  EXPECT_EQ(reader.counters().skipped_bytes, 4u);
}

// The set-up's reply check (FrontendInfo::find_refusal): "$OK" passes, the "$FAIL" line is returned.
TEST(UnicoreReplies, FindRefusalReturnsTheFailLine) {
  const std::string ok = "$OK*04\r\n$SNRSTAT,3,0,0,2*5C\r\n";
  EXPECT_EQ(find_refusal(bytes::as_bytes(ok)), "");
  const std::string refused = ok + "$FAIL,0*1E\r\n$OK*04\r\n";
  EXPECT_EQ(find_refusal(bytes::as_bytes(refused)), "$FAIL,0*1E");
}

}  // namespace
}  // namespace navfuse::frontends::unicore
