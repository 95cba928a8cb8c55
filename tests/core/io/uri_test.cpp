// URI parsing: the DESIGN.md forms, the listen forms, options, and one-line errors.
#include "core/io/uri.hpp"

#include <gtest/gtest.h>

namespace navfuse::io {
namespace {

std::string error_of(std::string_view text) {
  try {
    parse_uri(text);
  } catch (const UriError& e) {
    return e.what();
  }
  return "";
}

TEST(Uri, SerialForms) {
  const Uri u = parse_uri("serial:/dev/ttyUSB0?baud=921600");
  EXPECT_EQ(u.scheme, Scheme::kSerial);
  EXPECT_EQ(u.path, "/dev/ttyUSB0");
  EXPECT_EQ(u.option("baud", 0), 921600);
  EXPECT_EQ(u.option("reconnect_ms", 77), 77);
  EXPECT_EQ(parse_uri("serial:///dev/ttyACM1").path, "/dev/ttyACM1");
  EXPECT_EQ(parse_uri("serial:/dev/ttyS0?baud=115200&reconnect_ms=20&queue_bytes=0")
                .option("reconnect_ms", 0),
            20);
}

TEST(Uri, NetworkForms) {
  Uri u = parse_uri("tcp://127.0.0.1:5000");
  EXPECT_EQ(u.scheme, Scheme::kTcp);
  EXPECT_EQ(u.host, "127.0.0.1");
  EXPECT_EQ(u.port, 5000);
  u = parse_uri("tcp://gnss-box.local:2101?connect_timeout_ms=500");
  EXPECT_EQ(u.host, "gnss-box.local");
  EXPECT_EQ(u.option("connect_timeout_ms", 0), 500);
  u = parse_uri("tcp-listen://:30201");
  EXPECT_EQ(u.scheme, Scheme::kTcpListen);
  EXPECT_EQ(u.host, "");
  EXPECT_EQ(u.port, 30201);
  EXPECT_EQ(parse_uri("tcp-listen://127.0.0.1:0").port, 0);
  u = parse_uri("udp://192.168.1.10:9000");
  EXPECT_EQ(u.scheme, Scheme::kUdp);
  EXPECT_EQ(u.port, 9000);
  EXPECT_EQ(parse_uri("udp://:9000").scheme, Scheme::kUdpListen);  // empty host = listen
  u = parse_uri("udp-listen://127.0.0.1:9001");
  EXPECT_EQ(u.scheme, Scheme::kUdpListen);
  EXPECT_EQ(u.host, "127.0.0.1");
  u = parse_uri("tcp://[::1]:5000");
  EXPECT_EQ(u.host, "::1");
  EXPECT_EQ(u.port, 5000);
}

TEST(Uri, FileForms) {
  EXPECT_EQ(parse_uri("file:out/run.p1log").path, "out/run.p1log");
  EXPECT_EQ(parse_uri("file:/tmp/x.mip").path, "/tmp/x.mip");
  EXPECT_EQ(parse_uri("file:///tmp/x.mip").path, "/tmp/x.mip");
  EXPECT_EQ(parse_uri("file:-").path, "-");
}

TEST(Uri, BadFormsGiveOneLineErrors) {
  const std::pair<const char*, const char*> cases[] = {
      {"", "missing scheme"},
      {"/dev/ttyUSB0", "missing scheme"},
      {"ftp://host:21", "unknown scheme 'ftp'"},
      {"tcp:host:5000", "unknown scheme 'tcp'"},
      {"tcp://localhost", "missing ':PORT'"},
      {"tcp://:5000", "missing HOST (use tcp-listen://:PORT"},
      {"tcp://host:0", "port 0 is only for listening"},
      {"tcp://host:65536", "bad port '65536'"},
      {"tcp://host:50x", "bad port '50x'"},
      {"tcp://host:", "bad port ''"},
      {"tcp://host:5000/path", "unexpected '/'"},
      {"tcp://::1:5000", "put an IPv6 address in brackets"},
      {"tcp://[::1:5000", "unterminated '['"},
      {"udp://host", "missing ':PORT'"},
      {"serial:", "missing path"},
      {"serial:/dev/ttyUSB0?baud=12345", "unsupported baud rate 12345"},
      {"serial:/dev/ttyUSB0?baud=fast", "option 'baud' needs an integer value"},
      {"serial:/dev/ttyUSB0?baud", "option 'baud' needs an integer value"},
      {"serial:/dev/ttyUSB0?speed=9600", "unknown option 'speed' for serial (known: baud,"},
      {"serial:/dev/ttyUSB0?baud=9600&baud=9600", "option 'baud' given twice"},
      {"tcp://h:1?reconnect_ms=0", "option 'reconnect_ms' out of range [1,"},
      {"udp://h:1?baud=9600", "unknown option 'baud' for udp (it takes none)"},
      {"file:", "missing path"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string e = error_of(text);
    EXPECT_EQ(e.rfind("bad URI \"" + std::string(text) + "\": ", 0), 0u) << text << " -> " << e;
    EXPECT_NE(e.find(expected), std::string::npos) << text << " -> " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

}  // namespace
}  // namespace navfuse::io
