// NTRIP client pieces of `navfuse run --corrections` against the protocol's text (RTCM 10410.1
// examples of requests and answers; base64 values worked out apart, RFC 4648).
#include "apps/run/ntrip_protocol.hpp"

#include <gtest/gtest.h>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {
namespace {

std::vector<std::uint8_t> bytes(std::string_view s) { return {s.begin(), s.end()}; }

TEST(NtripSource, DefaultsToVersion2OnPort2101AndMasksThePassword) {
  const CorrectionsSource s = parse_corrections_source("ntrip://rover:pw@caster.example:2101/MOUNT1");
  EXPECT_TRUE(s.ntrip);
  EXPECT_EQ(s.version, 2);
  EXPECT_EQ(s.host, "caster.example");
  EXPECT_EQ(s.port, 2101);
  EXPECT_EQ(s.mount, "MOUNT1");
  EXPECT_EQ(s.user, "rover");
  EXPECT_EQ(s.password, "pw");
  EXPECT_EQ(s.text, "ntrip://rover:***@caster.example:2101/MOUNT1");
  const CorrectionsSource v1 = parse_corrections_source("ntrip://caster.example/M?version=1");
  EXPECT_EQ(v1.version, 1);
  EXPECT_EQ(v1.port, 2101);
  EXPECT_TRUE(v1.user.empty());
  const CorrectionsSource tcp = parse_corrections_source("tcp://10.0.0.5:5016");
  EXPECT_FALSE(tcp.ntrip);
  EXPECT_EQ(tcp.port, 5016);
}

TEST(NtripSource, GgaIntervalOptionForBothSchemes) {
  EXPECT_EQ(parse_corrections_source("ntrip://caster.example/M").gga_interval_s, 0.0);  // never by default
  const CorrectionsSource v1 = parse_corrections_source("ntrip://u:p@caster.example:2102/VRS?gga=10&version=1");
  EXPECT_EQ(v1.gga_interval_s, 10.0);
  EXPECT_EQ(v1.version, 1);
  EXPECT_EQ(v1.port, 2102);
  EXPECT_EQ(v1.mount, "VRS");
  EXPECT_EQ(v1.text, "ntrip://u:***@caster.example:2102/VRS?gga=10&version=1");
  const CorrectionsSource v2 = parse_corrections_source("ntrip://caster.example/VRS?version=2&gga=0.5");
  EXPECT_EQ(v2.gga_interval_s, 0.5);
  EXPECT_EQ(v2.version, 2);
  EXPECT_EQ(parse_corrections_source("ntrip://caster.example/VRS?gga=0").gga_interval_s, 0.0);
  const CorrectionsSource tcp = parse_corrections_source("tcp://10.0.0.5:5016?gga=5");
  EXPECT_EQ(tcp.gga_interval_s, 5.0);
  EXPECT_EQ(tcp.host, "10.0.0.5");
  EXPECT_EQ(tcp.port, 5016);
}

TEST(NtripSource, ErrorsDoNotShowThePassword) {
  for (const char* bad : {"ntrip://rover:s3cret@caster.example/M?gga=x", "ntrip://rover:s3cret@caster.example",
                          "ntrip://rover:s3cret@caster.example:0/M"}) {
    try {
      parse_corrections_source(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const CommandError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find("s3cret"), std::string::npos) << what;
      EXPECT_NE(what.find("rover:***@caster.example"), std::string::npos) << what;
    }
  }
}

TEST(NtripSource, RefusesWhatCannotBeAsked) {
  EXPECT_THROW(parse_corrections_source("ntrip://caster.example"), CommandError);          // no mountpoint
  EXPECT_THROW(parse_corrections_source("ntrip://caster.example/M?version=3"), CommandError);
  EXPECT_THROW(parse_corrections_source("tcp://caster.example"), CommandError);            // no port
  EXPECT_THROW(parse_corrections_source("http://caster.example/M"), CommandError);
  EXPECT_THROW(parse_corrections_source("tcp://h:99999"), CommandError);
  EXPECT_THROW(parse_corrections_source("ntrip://caster.example/M?gga=-1"), CommandError);
  EXPECT_THROW(parse_corrections_source("ntrip://caster.example/M?gga=ten"), CommandError);
  EXPECT_THROW(parse_corrections_source("ntrip://caster.example/M?gga="), CommandError);
  EXPECT_THROW(parse_corrections_source("ntrip://caster.example/M?gga=10&colour=red"), CommandError);
  EXPECT_THROW(parse_corrections_source("tcp://h:5016?version=1"), CommandError);  // no protocol to choose
}

TEST(NtripRequest, Version1And2AsTheStandardShowsThem) {
  CorrectionsSource s = parse_corrections_source("ntrip://navfuse:s3cret@127.0.0.1:2101/RTCM3?version=1");
  EXPECT_EQ(ntrip_request(s),
            "GET /RTCM3 HTTP/1.0\r\nUser-Agent: NTRIP navfuse/0.1\r\n"
            "Authorization: Basic bmF2ZnVzZTpzM2NyZXQ=\r\n\r\n");
  s = parse_corrections_source("ntrip://ab@127.0.0.1:2101/RTCM3");  // user "ab", empty password: "ab:" = YWI6
  EXPECT_EQ(ntrip_request(s),
            "GET /RTCM3 HTTP/1.1\r\nHost: 127.0.0.1:2101\r\nNtrip-Version: Ntrip/2.0\r\n"
            "User-Agent: NTRIP navfuse/0.1\r\nAuthorization: Basic YWI6\r\nConnection: close\r\n\r\n");
}

// The rover position of rover_position_test.cpp: 52.5163 N 13.3777 E, 40.5 m above the geoid,
// RTK fixed with 12 satellites at 11:59:42 UTC. Checksum 0x6C: the XOR of the characters between
// '$' and '*', worked out apart from navfuse.
constexpr std::string_view kGga = "$GNGGA,115942.00,5230.978000,N,01322.662000,E,4,12,,40.500,M,39.500,M,,*6C\r\n";

TEST(NtripRequest, Version2CarriesThePositionInTheNtripGgaHeader) {
  const CorrectionsSource s = parse_corrections_source("ntrip://ab@127.0.0.1:2101/VRS?gga=10");
  EXPECT_EQ(ntrip_request(s, kGga),
            "GET /VRS HTTP/1.1\r\nHost: 127.0.0.1:2101\r\nNtrip-Version: Ntrip/2.0\r\n"
            "User-Agent: NTRIP navfuse/0.1\r\nAuthorization: Basic YWI6\r\n"
            "Ntrip-GGA: $GNGGA,115942.00,5230.978000,N,01322.662000,E,4,12,,40.500,M,39.500,M,,*6C\r\n"
            "Connection: close\r\n\r\n");
}

TEST(NtripRequest, Version1SendsThePositionAfterTheRequest) {
  const CorrectionsSource s = parse_corrections_source("ntrip://ab@127.0.0.1:2101/VRS?gga=10&version=1");
  EXPECT_EQ(ntrip_request(s, kGga),
            "GET /VRS HTTP/1.0\r\nUser-Agent: NTRIP navfuse/0.1\r\nAuthorization: Basic YWI6\r\n\r\n"
            "$GNGGA,115942.00,5230.978000,N,01322.662000,E,4,12,,40.500,M,39.500,M,,*6C\r\n");
}

TEST(NtripRequest, NoPositionYetIsThePlainRequest) {
  for (const char* uri : {"ntrip://ab@127.0.0.1:2101/VRS?gga=10", "ntrip://ab@127.0.0.1:2101/VRS?gga=10&version=1"}) {
    const CorrectionsSource s = parse_corrections_source(uri);
    EXPECT_EQ(ntrip_request(s, ""), ntrip_request(s)) << uri;
    EXPECT_EQ(ntrip_request(s).find("GGA"), std::string::npos) << uri;
  }
}

TEST(NtripAnswer, AcceptsIcyAndHttp200AndExplainsRefusals) {
  EXPECT_FALSE(parse_ntrip_answer("ICY 20", "M").has_value());  // incomplete
  auto a = parse_ntrip_answer("ICY 200 OK\r\n\xd3\x00", "M");
  ASSERT_TRUE(a.has_value());
  EXPECT_TRUE(a->ok);
  EXPECT_EQ(a->header_bytes, 12u);
  a = parse_ntrip_answer("HTTP/1.1 200 OK\r\nNtrip-Version: Ntrip/2.0\r\nTransfer-Encoding: Chunked\r\n\r\n", "M");
  ASSERT_TRUE(a.has_value());
  EXPECT_TRUE(a->ok);
  EXPECT_TRUE(a->chunked);
  a = parse_ntrip_answer("SOURCETABLE 200 OK\r\n", "M");
  ASSERT_TRUE(a.has_value());
  EXPECT_FALSE(a->ok);
  EXPECT_NE(a->reason.find("no mountpoint 'M'"), std::string::npos);
  a = parse_ntrip_answer("HTTP/1.1 401 Unauthorized\r\n\r\n", "M");
  ASSERT_TRUE(a.has_value());
  EXPECT_FALSE(a->ok);
  EXPECT_NE(a->reason.find("password"), std::string::npos);
}

TEST(ChunkedDecoder, UndoesChunksSplitAnywhere) {
  const std::string wire = "4\r\nWiki\r\n5;name=x\r\npedia\r\nE\r\n in\r\n\r\nchunks.\r\n0\r\n\r\n";  // RFC 9112 style
  for (std::size_t split = 1; split <= wire.size(); ++split) {
    ChunkedDecoder d;
    std::vector<std::uint8_t> out;
    for (std::size_t i = 0; i < wire.size(); i += split) {
      ASSERT_TRUE(d.feed(bytes(std::string_view(wire).substr(i, split)), out)) << split;
    }
    EXPECT_EQ(std::string(out.begin(), out.end()), "Wikipedia in\r\n\r\nchunks.") << split;
    EXPECT_TRUE(d.ended());
  }
}

TEST(ChunkedDecoder, RefusesAMalformedStream) {
  ChunkedDecoder d;
  std::vector<std::uint8_t> out;
  EXPECT_FALSE(d.feed(bytes("zz\r\n"), out));
  ChunkedDecoder missing_crlf;
  EXPECT_FALSE(missing_crlf.feed(bytes("2\r\nabX"), out));
}

}  // namespace
}  // namespace navfuse::apps
