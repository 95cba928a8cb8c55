// The checksummed ASCII examples of the digest §9.3 (every one verified there): those that verify
// are accepted, those the digest shows to be wrong are rejected for their checksum, and the
// async outputs decode to the values printed.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rotation/rotation.hpp"
#include "core/time/gps_time.hpp"
#include "frontends/vectornav/ascii_sentence.hpp"
#include "test_support.hpp"

namespace navfuse::frontends::vectornav {
namespace {

using rot::kDegToRad;

// Sentences whose checksum the digest verified (ICD line numbers in the digest table).
const char* const kGood[] = {
    "$VNRRG,11*73",
    "$VNRRG,5*46",
    "$VNRRG,5,115200*6D",
    "$VNWNV*57",
    "$VNRFS*5F",
    "$VNRST*4D",
    "$VNFWU*5C",
    "$VNKMD,1*47",
    "$VNKAD,1*4B",
    "$VNSIH,73.2*7E",
    "$VNSIH,73.2,87.1,10.2*73",
    "$VNSIH,-0.3574,0.5894,0.3812,0.6161*6A",
    "$VNASY,1*4E",
    "$VNSFB*4F",
    "$VNSBL,1*58",
    "$VNSBL,?*56",
    "$VNBOM,1*45",
    "$VNRRG,00,*5F",
    "$VNWRG,00,ABCDEF123*6D",
    "$VNRRG,05,115200*5D",
    "$VNRRG,06,0*69",
    "$VNRRG,07,10*59",
    "$VNWRG,07,10*5C",
    "$VNRRG,30,0,0,0,0,1,0,1*6C",
    "$VNYPR,+010.071,+000.278,-002.026,T1162704*2F",
    "$VNYPR,+010.071,+000.278,-002.026,S0000*1F",
    "$VNYPR,+010.071,+000.278,-002.026,T1162704,S0000*50",
    "$VNYPR,+010.071,+000.278,-002.026*60",
    "$VNERR,03*72",
    "$VNRRG,32,3,0,0,0,6,1,0,100000000,0*6B",
    "$VNWRG,32,5,1,1,0,1,0,1,100000,0*5F",
    "$VNRRG,75,0,0,00*5D",
    "$VNWRG,75,1,160,0*6E",
    "$VNRRG,76,0,0,00*5E",
    "$VNWRG,76,1,160,0*6D",
    "$VNRRG,77,0,0,00*5F",
    "$VNWRG,77,1,160,0*6C",
    "$VNRRG,101,0,0,0,0,00000000*6F",
    "$VNWRG,101,1,1,0,0,1*5B",
    "$VNRRG,206,0,0,0,0*47",
    "$VNRRG,21,0.231773,0.0105909,0.421698,1.16676E-05,3.9404E-05,-9.79498*63",
    "$VNRRG,35,1,1,1,1*75",
    "$VNWRG,36,4,3,2,4,3,2,4,3,2*6A",
    "$VNRRG,23,1,0,0,0,1,0,0,0,1,0,0,0*73",
    "$VNWRG,23,0.71,0.011,0.012,0.013,0.72,0.014,0.015,0.016,0.73,0.1,0.2,0.3*47",
    "$VNRRG,26,1,0,0,0,1,0,0,0,1*6A",
    "$VNWRG,26,1,0,0,0,-1,0,0,0,-1*6F",
    "$VNRRG,82,0,0,0,0,0*65",
    "$VNWRG,82,1,1,1,0,0*61",
    "$VNRRG,85,0,2,2,2,0,0,3,3,3,0*7F",
    "$VNRRG,44,0,1,5*6B",
    "$VNRRG,50,0,0,0*6A",
    "$VNWRG,50,1,2,3*6F",
    "$VNRRG,51,1,0.1,0.01*5A",
    "$VNRRG,55,0,0,5,0,1*6B",
    "$VNRRG,57,0,0,0*6D",
    "$VNRRG,99,0013,10,10,16,02,EBF9,003F,0000*79",
    "$VNRRG,100,2,1,0,0,1000000,100000,0*6D",
    "$VNRRG,157,0,0,0*5C",
    "$VNWRG,157,1,1,1*58",
    "$VNRRG,67,3,1,1,0*71",
    "$VNWRG,74,0.01,0.01,0.01,0.01,0.01,0.01,0.01*46",
    "$VNRRG,105,+00.000,+00.000,+00.000,00.0000,00.0000,00.0000*5C",
    "$VNRRG,144,05,2,5,01,0,0*41",
    "$VNWRG,83,0,0,0,0,10,2014,30,-94,100*45",
    "$VNRRG,93,+01.000,+00.000,+00.000,00.0254,00.0254,00.0254*60",
    "$VNRRG,116,0,0.05,20,0.05,0.08,0,0*4D",
    "$VNRRG,01,VN-300T-DEV*76",
    "$VNRRG,02,3*6E",
    "$VNRRG,03,0100055765*59",
    "$VNRRG,04,1.1.0.1*74",
    "$VNRRG,33,0,4294967295,6049*69",
    "$VNRRG,08,-177.483,+000.594,+004.534*54",
    "$VNRRG,09,-0.005850,+0.039090,+0.998955,-0.022956*7A",
    "$VNRRG,15,-0.005738,+0.038845,+0.998947,-0.023725,-00.2250,-00.0292,+00.4195,+00.102,-00.769,-09.765,"
    "+00.003204,-00.000344,-00.000193*68",
    "$VNRRG,27,-177.368,+000.575,+004.469,-00.2286,-00.0221,+00.4197,+00.103,-00.759,-09.766,-00.002229,+00.000935,"
    "+00.000270*40",
    "$VNRRG,239,-178.521,+000.546,+004.375,+00.023,+00.007,+00.002,-00.001353,-00.000030,+00.000157*5E",
    "$VNRRG,240,-178.541,+000.533,+004.373,+00.021,+00.005,+00.003,+00.000280,-00.000497,+00.000436*50",
    "$VNRRG,17,-00.2261,-00.0312,+00.4227*58",
    "$VNRRG,18,+00.128,-00.768,-09.748*63",
    "$VNRRG,19,+00.003475,+00.001332,-00.000664*56",
    "$VNRRG,20,-00.2246,-00.0201,+00.4177,+00.083,-00.757,-09.772,+00.003114,-00.000292,-00.000966*6E",
    "$VNRRG,54,-00.2258,-00.0251,+00.4185,+00.121,-00.790,-09.768,+00.004292,+00.000511,+00.058117,+35.5,"
    "+099.652*54",
    "$VNRRG,80,+709.377502,+151.806,+101.446,+2373.961,-508.016,-289.134,-6842.994*6B",
    "$VNRRG,47,1,0,0,0,1,0,0,0,1,0,0,0*71",
    "$VNRRG,58,501342.999609,2303,4,16,+32.89195850,-096.70376580,+00163.653,-000.005,+000.005,+000.108,+001.433,"
    "+001.439,+003.605,+000.173,3.00E-09*03",
    "$VNRRG,59,501363.599629,2303,4,16,-0625836.586,-5324474.571,+3443992.083,-000.011,+000.007,+000.050,+001.411,"
    "+001.445,+003.653,+000.118,3.00E-09*3E",
    "$VNRRG,103,501549.400155,2303,4,16,+32.89194870,-096.70376330,+00164.770,-000.020,+000.011,-000.183,+001.580,"
    "+001.461,+003.766,+000.170,3.00E-09*3F",
    "$VNRRG,104,501570.000185,2303,4,16,-0625836.836,-5324476.051,+3443991.753,+000.016,+000.104,-000.064,+001.630,"
    "+001.534,+003.595,+000.228,3.00E-09*00",
    "$VNRRG,63,501384.439541,2303,9306,-177.963,+000.511,+004.425,+32.89195732,-096.70376518,+00164.947,-000.014,"
    "-000.005,-000.094,01.43,00.56,0.090*68",
    "$VNRRG,64,501405.034554,2303,8306,-178.076,+000.501,+004.383,-0625836.892,-5324476.432,+3443993.281,-000.002,"
    "-000.059,+000.027,01.43,00.54,0.091*53",
    "$VNRRG,72,-178.157,+000.548,+004.411,+32.89195757,-096.70376187,+00165.684,+000.001,-000.010,-000.045,+00.079,"
    "-00.760,-09.766,+00.002244,-00.001463,-00.000142*58",
    "$VNRRG,73,-178.238,+000.518,+004.411,-625836.73327794,-5324475.25873416,+3443992.824,-000.014,-000.019,+000.012,"
    "+00.090,-00.763,-09.776,+00.001156,-00.000218,-00.000353*52",
    "$VNRRG,86,20,19,50,20,21,50,20,19*7C",
    "$VNRRG,97,0,0,0,+00.000,+00.000,+00.000,00.0000,00.0000,00.0000*7A",
    "$VNRRG,98,100,-178.774*4A",
    "$VNRRG,115,+00.000,+00.000,+00.000*5F",
    // Typo'd ICD sentences, accepted once the typo is corrected (errata A5/A6).
    "$VNWRG,75,1,10,11,0009,0100*60",
    "$VNWRG,75,1,10,90,10,0100,8001,0002*6A",
    "$VNWRG,57,1,1,1*69",
};

// Printed in the ICD with checksums that do not verify (digest §9.3, §10 A4-A6).
const char* const kBad[] = {
    "$VNWRG,5,921600*46",                             // L217 (correct: 63)
    "$VNWRG,5,921600*6D",                             // L219
    "$VNERR, 03*72",                                  // L2882 typeset space
    "$VNW RG,57,1,1,1*69",                            // L3850
    "$VNRG,03,0100055765*59",                         // L4348
    "$VNRG,75,1,10,11,0009,0100*60",                  // L5225
    "$VNW RG, 75, 1, 10, 90, 10, 0100, 8001, 0002*6A",  // L5378
};

// The verified example starting with `prefix`.
const char* good(std::string_view prefix) {
  for (const char* s : kGood)
    if (std::string_view(s).starts_with(prefix)) return s;
  ADD_FAILURE() << "no example " << prefix;
  return "";
}

std::vector<std::uint8_t> line(const char* s) { return test::text_bytes(std::string(s) + "\r\n"); }

TEST(VnAsciiVectors, EveryVerifiedExampleIsAccepted) {
  for (const char* s : kGood) {
    VnStreamDecoder d;
    test::CollectingSink sink(true);
    test::decode_all(d, line(s), sink);
    EXPECT_EQ(d.counters().frames, 1u) << s;
    EXPECT_EQ(d.counters().bad_frames, 0u) << s;
    EXPECT_EQ(d.counters().decode_errors, 0u) << s;
    EXPECT_EQ(d.counters().unknown_frames, 0u) << s;
    EXPECT_EQ(sink.records.size(), 1u) << s;
  }
}

TEST(VnAsciiVectors, WrongChecksumsAreRejected) {
  for (const char* s : kBad) {
    VnStreamDecoder d;
    test::CollectingSink sink;
    test::decode_all(d, line(s), sink);
    EXPECT_EQ(d.counters().frames, 0u) << s;
    EXPECT_EQ(d.counters().bad_frames, 1u) << s;
    EXPECT_EQ(d.counters().skipped_bytes, std::string(s).size() + 2) << s;
  }
  // L217's sentence with the correct XOR (digest A4) is accepted.
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, line("$VNWRG,5,921600*63"), sink);
  EXPECT_EQ(d.counters().frames, 1u);
}

TEST(VnAsciiVectors, CrcModeAndBypass) {
  // Digest §2.3 derived CRC16 values; bypass with XX (L591-597) and XXXX (errata A26).
  for (const char* s : {"$VNRRG,5*D5A3", "$VNRRG,11*D26E", "$VNWNV*DBDF", "$VNRST*6542",
                        "$VNYPR,+010.071,+000.278,-002.026*29F8", "$VNRRG,08,-177.483,+000.594,+004.534*6CC8",
                        "$VNRRG,1*XX", "$VNYPR,+010.071,+000.278,-002.026*XXXX"}) {
    VnStreamDecoder d;
    test::CollectingSink sink;
    test::decode_all(d, line(s), sink);
    EXPECT_EQ(d.counters().frames, 1u) << s;
  }
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, line("$VNRRG,5*D5A4"), sink);
  EXPECT_EQ(d.counters().bad_frames, 1u);
  // Bare "\n" terminators are accepted too (errata A27).
  VnStreamDecoder d2;
  test::decode_all(d2, test::text_bytes("$VNRRG,5*46\n"), sink);
  EXPECT_EQ(d2.counters().frames, 1u);
}

TEST(VnAsciiVectors, AppendsInEitherOrder) {
  AsciiSentence a;
  ASSERT_TRUE(parse_sentence("VNYPR,+010.071,+000.278,-002.026,T1162704,S0000", true, a));
  EXPECT_EQ(a.field_count, 3u);
  EXPECT_TRUE(a.has_append_count);
  EXPECT_EQ(a.append_count, 1162704u);
  EXPECT_TRUE(a.has_append_status);
  AsciiSentence b;
  ASSERT_TRUE(parse_sentence("VNYPR,+010.071,+000.278,-002.026,S00A3,T17", true, b));
  EXPECT_EQ(b.field_count, 3u);
  EXPECT_EQ(b.append_status, 0x00A3);
  EXPECT_EQ(b.append_count, 17u);
}

TEST(VnAsciiVectors, InsSolutionDecodesToPrintedValues) {
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, line(good("$VNRRG,63,")), sink);  // Reg 63 example (L4900)
  ASSERT_EQ(sink.count(MeasurementKind::kDeviceSolution), 1u);
  const auto& s = std::get<NavSolution>(sink.measurements[0]);
  EXPECT_EQ(s.header.time_source, TimeSource::kGps);
  EXPECT_EQ(s.header.time_ns, time::gps_ns_from_week_tow(2303, 501384.439541));
  EXPECT_EQ(s.device_status, 0x9306u);
  // 0x9306: Mode 2 (tracking), GnssFix, compass FixAiding (digest §2.6); bits 12, 15 ignored.
  EXPECT_EQ(s.mode, NavMode::kNavigation);
  EXPECT_TRUE(s.status_flags & NavSolution::kStatusDualAntennaHeading);
  EXPECT_NEAR(s.rpy_rad.z(), -177.963 * kDegToRad, 1e-12);
  EXPECT_NEAR(s.rpy_rad.x(), 4.425 * kDegToRad, 1e-12);
  EXPECT_NEAR(s.lat_rad, 32.89195732 * kDegToRad, 1e-15);
  EXPECT_NEAR(s.lon_rad, -96.70376518 * kDegToRad, 1e-15);
  EXPECT_DOUBLE_EQ(s.height_m, 164.947);
  EXPECT_DOUBLE_EQ(s.vel_ned_mps.z(), -0.094);
  EXPECT_DOUBLE_EQ(s.pos_std_ned_m.x(), 0.56);
  EXPECT_DOUBLE_EQ(s.vel_std_ned_mps.y(), 0.090);
  EXPECT_NEAR(s.att_std_rpy_rad.z(), 1.43 * kDegToRad, 1e-15);
}

TEST(VnAsciiVectors, GnssSolutionsDecodeAndEcefAgreesWithLla) {
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, line(good("$VNRRG,58,")), sink);  // Reg 58 (L4708)
  test::decode_all(d, line(good("$VNRRG,59,")), sink);  // Reg 59 (L4754), 20 s later, same bench
  ASSERT_EQ(sink.count(MeasurementKind::kGnssPosition), 2u);
  const auto& lla = std::get<GnssPosition>(sink.measurements[0]);
  const auto& ecef = std::get<GnssPosition>(sink.measurements[2]);
  EXPECT_EQ(lla.fix, GnssFixType::kSbas);
  EXPECT_EQ(lla.num_sats, 16);
  EXPECT_DOUBLE_EQ(lla.cov_ned_m2(2, 2), 3.605 * 3.605);
  // The ECEF example is the same static antenna: within a few metres of the LLA example.
  EXPECT_NEAR(ecef.lat_rad, lla.lat_rad, 5.0 / 6.4e6);
  EXPECT_NEAR(ecef.lon_rad, lla.lon_rad, 5.0 / 5.4e6);
  EXPECT_NEAR(ecef.height_m, lla.height_m, 5.0);
  // Rotated ECEF sigmas keep their total variance.
  EXPECT_NEAR(ecef.cov_ned_m2.trace(), 1.411 * 1.411 + 1.445 * 1.445 + 3.653 * 3.653, 1e-9);
  const auto& v = std::get<GnssVelocity>(sink.measurements[1]);
  EXPECT_DOUBLE_EQ(v.vel_ned_mps.z(), 0.108);
  EXPECT_DOUBLE_EQ(v.cov_ned_m2ps2(0, 0), 0.173 * 0.173);
}

TEST(VnAsciiVectors, ImuDeltaAndCompassRegisters) {
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, line(good("$VNRRG,54,")), sink);  // Reg 54 IMU
  test::decode_all(d, line(good("$VNRRG,80,")), sink);  // Reg 80 DTV
  test::decode_all(d, line(good("$VNRRG,98,")), sink);  // Reg 98 compass
  ASSERT_EQ(sink.count(MeasurementKind::kImu), 2u);
  ASSERT_EQ(sink.count(MeasurementKind::kMagnetometer), 1u);
  ASSERT_EQ(sink.count(MeasurementKind::kPressure), 1u);
  ASSERT_EQ(sink.count(MeasurementKind::kGnssHeading), 1u);
  for (const auto& m : sink.measurements) {
    if (const auto* s = std::get_if<ImuSample>(&m); s && s->quantity == ImuQuantity::kRates) {
      EXPECT_DOUBLE_EQ(s->accel.z(), -9.768);
      EXPECT_DOUBLE_EQ(s->gyro.z(), 0.058117);
    } else if (s) {
      EXPECT_DOUBLE_EQ(s->dt_s, 709.377502);
      EXPECT_NEAR(s->gyro.x(), 151.806 * kDegToRad, 1e-12);  // degrees on the wire
    } else if (const auto* p = std::get_if<Pressure>(&m)) {
      EXPECT_DOUBLE_EQ(p->pressure_pa, 99652.0);
    } else if (const auto* h = std::get_if<GnssHeading>(&m)) {
      EXPECT_NEAR(h->heading_rad, -178.774 * kDegToRad, 1e-12);
      EXPECT_TRUE(h->header.valid & GnssHeading::kValidHeading);
    }
  }
}

TEST(VnAsciiVectors, ErrorReplyNamesTheCode) {
  VnStreamDecoder d;
  test::CollectingSink sink(true);
  test::decode_all(d, line("$VNERR,03*72"), sink);
  ASSERT_EQ(sink.records.size(), 1u);
  EXPECT_EQ(std::get<std::string>(*test::field(sink.records[0], "error_name")), "invalid_checksum");
}

TEST(VnAsciiVectors, NmeaIsFramedButUnknown) {
  VnStreamDecoder d;
  test::CollectingSink sink;
  test::decode_all(d, line("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47"), sink);
  EXPECT_EQ(d.counters().frames, 1u);
  EXPECT_EQ(d.counters().unknown_frames, 1u);
}

}  // namespace
}  // namespace navfuse::frontends::vectornav
