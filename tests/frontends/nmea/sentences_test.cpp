// NMEA sentences of the UM220 (Unicore spec §5.4): every checksummed example of digest §10.1
// decodes to the printed values and re-encodes to the same bytes; the examples the digest shows
// to be wrong are rejected for their checksum; random round trips for every sentence type.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/bytes/checks.hpp"
#include "frontends/nmea/framer.hpp"
#include "frontends/nmea/sentences.hpp"

namespace navfuse::frontends::nmea {
namespace {

// Frames one sentence (appending "\r\n") and splits it; nullopt if the framer rejects it.
struct Framed {
  std::string body;
  Fields fields;
};
std::optional<Framed> frame(const std::string& sentence) {
  SentenceFramer f;
  std::optional<Framed> out;
  const std::string line = sentence + "\r\n";
  f.feed(bytes::as_bytes(line), [&](const Frame& fr) { out = Framed{std::string(fr.body), {}}; });
  if (out) out->fields.split(out->body);
  return out;
}

template <class T>
std::string reencode(const T& s) {
  std::vector<std::uint8_t> out;
  EXPECT_TRUE(encode(s, out));
  std::string text(out.begin(), out.end());
  if (text.size() >= 2) text.resize(text.size() - 2);  // drop "\r\n"
  return text;
}

double minutes_to_deg(double deg, double minutes) { return deg + minutes / 60.0; }

TEST(NmeaExamples, GgaH51) {
  const std::string s = "$GPGGA,060845.00,4004.74005,N,11614.19613,E,1,10,0.85,53.5,M,,M,,*7B";  // L868
  const auto fr = frame(s);
  ASSERT_TRUE(fr);
  const auto m = decode_gga(fr->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->time->ns, ((6 * 60 + 8) * 60 + 45) * 1'000'000'000LL);
  EXPECT_NEAR(m->lat->deg, minutes_to_deg(40, 4.74005), 1e-12);
  EXPECT_NEAR(m->lon->deg, minutes_to_deg(116, 14.19613), 1e-12);
  EXPECT_EQ(m->quality, 1u);
  EXPECT_EQ(m->num_sats->value, 10u);
  EXPECT_DOUBLE_EQ(m->hdop->value, 0.85);
  EXPECT_DOUBLE_EQ(m->height_m->value, 53.5);
  EXPECT_FALSE(m->geoid_separation_m);  // CFGGEOID=0: ellipsoid height, Altref empty (L885)
  EXPECT_EQ(reencode(*m), s);
}

TEST(NmeaExamples, GgaH30WithArtifactSpaceRemoved) {
  // L1090 with the text-extraction space removed (digest §10.1).
  const std::string s = "$GPGGA,063952.000,4002.229934,N,11618.096855,E,1,4,2.788,37.254,M,0,M,,*76";
  const auto m = decode_gga(frame(s)->fields);
  ASSERT_TRUE(m);
  EXPECT_NEAR(m->lat->deg, minutes_to_deg(40, 2.229934), 1e-12);
  EXPECT_NEAR(m->lon->deg, minutes_to_deg(116, 18.096855), 1e-12);
  EXPECT_DOUBLE_EQ(m->height_m->value, 37.254);
  EXPECT_DOUBLE_EQ(m->geoid_separation_m->value, 0.0);
  EXPECT_EQ(reencode(*m), s);
  // As printed (with the space) the checksum does not match.
  EXPECT_FALSE(frame("$GPGGA,063952.000,4002.229934,N,11618.096855,E,1,4,2.788,37.254,M,0 ,M,,*77"));
}

TEST(NmeaExamples, GllBothDialects) {
  const std::string s = "$GPGLL,4004.74005,N,11614.19613,E,060845.00,A,A*6F";  // L900
  const auto m = decode_gll(frame(s)->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->status, 'A');
  EXPECT_EQ(*m->mode, 'A');
  EXPECT_EQ(reencode(*m), s);
  // L1123 as printed: checksum 5B, the XOR of the text is 5D (digest §11 item 21).
  EXPECT_FALSE(frame("$GPGLL,4002.217867,N,11618.105743,E,123400.000,A,A*5B"));
  const auto fixed = frame("$GPGLL,4002.217867,N,11618.105743,E,123400.000,A,A*5D");
  ASSERT_TRUE(fixed);
  const auto h30 = decode_gll(fixed->fields);
  ASSERT_TRUE(h30);
  EXPECT_NEAR(h30->lat->deg, minutes_to_deg(40, 2.217867), 1e-12);
  EXPECT_EQ(h30->time->ns, ((12 * 60 + 34) * 60) * 1'000'000'000LL);
}

TEST(NmeaExamples, GsaFixedCommasAndPrintedOnesRejected) {
  // L924 needs one more comma, L1148 three more (digest §11 item 19); as printed they fail.
  EXPECT_FALSE(frame("$GPGSA,A,3,02,03,06,09,12,17,19,23,28,25,,1.34,0.85,1.04,1*1E"));
  EXPECT_FALSE(frame("$GPGSA,A,3,14,22,18,31,,,,,,5.572,2.788,4.824*36"));
  const std::string h51 = "$GPGSA,A,3,02,03,06,09,12,17,19,23,28,25,,,1.34,0.85,1.04,1*1E";
  const auto m = decode_gsa(frame(h51)->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->dialect, Dialect::kH51);
  EXPECT_EQ(m->fix, 3u);
  const unsigned used[] = {2, 3, 6, 9, 12, 17, 19, 23, 28, 25};
  for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(m->sats[i]->value, used[i]);
  EXPECT_FALSE(m->sats[10]);
  EXPECT_DOUBLE_EQ(m->pdop->value, 1.34);
  EXPECT_DOUBLE_EQ(m->hdop->value, 0.85);
  EXPECT_DOUBLE_EQ(m->vdop->value, 1.04);
  EXPECT_EQ(m->system_id->value, 1u);
  EXPECT_EQ(reencode(*m), h51);
  const std::string h30 = "$GPGSA,A,3,14,22,18,31,,,,,,,,,5.572,2.788,4.824*36";
  const auto m30 = decode_gsa(frame(h30)->fields);
  ASSERT_TRUE(m30);
  EXPECT_EQ(m30->dialect, Dialect::kH30);
  EXPECT_DOUBLE_EQ(m30->vdop->value, 4.824);
  EXPECT_EQ(reencode(*m30), h30);
}

TEST(NmeaExamples, GsvAllElevenSentences) {
  const char* h51[] = {
      "$GPGSV,3,01,11,02,34,277,41,03,16,043,35,05,04,215,35,06,69,333,48,0*57",
      "$GPGSV,3,02,11,09,25,110,41,12,31,305,43,17,55,116,46,19,76,088,46,0*56",
      "$GPGSV,3,03,11,23,23,077,40,25,04,328,32,28,05,171,36,0*67",
      "$GBGSV,3,01,12,01,37,145,42,02,34,225,39,03,44,188,42,04,25,123,37,0*4C",
      "$GBGSV,3,02,12,05,17,249,36,06,30,169,38,07,03,188,31,08,69,027,43,0*4E",
      "$GBGSV,3,03,12,09,09,186,34,10,15,211,36,12,26,306,40,13,60,316,44,0*48"};
  const char* h30[] = {"$GPGSV,3,1,11,3,82,133,50,6,70,73,50,7,21,311,45,13,46,275,50*75",
                       "$GPGSV,3,2,11,16,52,51,49,19,52,194,49,21,12,49,37,23,40,222,49*7C",
                       "$GPGSV,3,3,11,30,31,69,46,31,8,127,19,1,5,,44*77",
                       "$BDGSV,2,1,5,161,35,140,47,163,33,224,47,164,24,124,43,167,47,73,48*65",
                       "$BDGSV,2,2,5,168,5,,50*52"};
  for (const char* s : h51) {
    const auto fr = frame(s);
    ASSERT_TRUE(fr) << s;
    const auto m = decode_gsv(fr->fields);
    ASSERT_TRUE(m) << s;
    EXPECT_EQ(m->dialect, Dialect::kH51);
    EXPECT_EQ(m->signal_id->value, 0u);
    EXPECT_EQ(reencode(*m), s);
  }
  for (const char* s : h30) {
    const auto m = decode_gsv(frame(s)->fields);
    ASSERT_TRUE(m) << s;
    EXPECT_EQ(m->dialect, Dialect::kH30);
    EXPECT_EQ(reencode(*m), s);
  }
  // Values of the first and the last (one satellite, empty azimuth) sentence.
  const auto first = decode_gsv(frame(h51[0])->fields);
  EXPECT_EQ(first->sats_in_view.value, 11u);
  EXPECT_EQ(first->sats[3].number.value, 6u);
  EXPECT_EQ(first->sats[3].elevation_deg->value, 69u);
  EXPECT_EQ(first->sats[3].azimuth_deg->value, 333u);
  EXPECT_EQ(first->sats[3].cn0_dbhz->value, 48u);
  const auto last = decode_gsv(frame(h30[4])->fields);
  EXPECT_EQ(last->sat_count, 1u);
  EXPECT_EQ(last->sats[0].number.value, 168u);
  EXPECT_EQ(sat_from_nmea(168, last->talker, Dialect::kH30).prn, 8);
  EXPECT_FALSE(last->sats[0].azimuth_deg);
  EXPECT_EQ(last->sats[0].cn0_dbhz->value, 50u);
}

TEST(NmeaExamples, RmcBothDialects) {
  EXPECT_FALSE(frame("$GPRMC,060845.00,A,4004.74005,N,11614.19613,E,0.000,,180817,,A,V*0B"));  // L982
  const std::string h51 = "$GPRMC,060845.00,A,4004.74005,N,11614.19613,E,0.000,,180817,,,A,V*0B";
  const auto m = decode_rmc(frame(h51)->fields);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->dialect, Dialect::kH51);
  EXPECT_EQ(m->date->year, 2017);
  EXPECT_EQ(m->date->month, 8);
  EXPECT_EQ(m->date->day, 18);
  EXPECT_DOUBLE_EQ(m->speed_knots->value, 0.0);
  EXPECT_FALSE(m->course_deg);
  EXPECT_EQ(*m->mode, 'A');
  EXPECT_EQ(*m->nav_status, 'V');
  EXPECT_EQ(reencode(*m), h51);
  const std::string h30 = "$GPRMC,123400.000,A,4002.217821,N,11618.105743,E,0.026,181.631,180411,,E,A*28";
  const auto m30 = decode_rmc(frame(h30)->fields);
  ASSERT_TRUE(m30);
  EXPECT_EQ(m30->dialect, Dialect::kH30);
  EXPECT_DOUBLE_EQ(m30->course_deg->value, 181.631);
  EXPECT_EQ(*m30->variation_direction, 'E');  // h30 constant E (L1224)
  EXPECT_EQ(m30->date->year, 2011);
  EXPECT_EQ(reencode(*m30), h30);
}

TEST(NmeaExamples, VtgZdaGst) {
  for (const char* s : {"$GPVTG,,T,,M,0.000,N,0.000,K,A*23", "$GNVTG,0.000,T,,M,0.000,N,0.000,K,A*13"}) {
    const auto m = decode_vtg(frame(s)->fields);
    ASSERT_TRUE(m) << s;
    EXPECT_EQ(*m->mode, 'A');
    EXPECT_EQ(reencode(*m), s);
  }
  const std::string zda = "$GNZDA,083927.000,21,11,2013,00,00*4C";  // L1259
  const auto z = decode_zda(frame(zda)->fields);
  ASSERT_TRUE(z);
  EXPECT_EQ(z->year->value, 2013u);
  EXPECT_EQ(z->month->value, 11u);
  EXPECT_EQ(z->day->value, 21u);
  EXPECT_EQ(z->time->ns, ((8 * 60 + 39) * 60 + 27) * 1'000'000'000LL);
  EXPECT_EQ(reencode(*z), zda);
  EXPECT_EQ(reencode(*decode_zda(frame("$GPZDA,060845.00,18,08,2017,00,00*6C")->fields)),
            "$GPZDA,060845.00,18,08,2017,00,00*6C");
  EXPECT_FALSE(frame("$GPGST,060845.00,0.6,,,0.07,0.09,0.09*47"));  // L1064 as printed
  const std::string gst = "$GPGST,060845.00,0.6,,,,0.07,0.09,0.09*47";
  const auto g = decode_gst(frame(gst)->fields);
  ASSERT_TRUE(g);
  EXPECT_DOUBLE_EQ(g->range_rms_m->value, 0.6);
  EXPECT_FALSE(g->std_major_m);
  EXPECT_DOUBLE_EQ(g->std_lat_m->value, 0.07);
  EXPECT_DOUBLE_EQ(g->std_lon_m->value, 0.09);
  EXPECT_DOUBLE_EQ(g->std_alt_m->value, 0.09);
  EXPECT_EQ(reencode(*g), gst);
}

TEST(NmeaSentences, WrongFieldCountsAndBadFieldsAreRejected) {
  Fields f;
  f.split("GPGGA,060845.00,4004.74005,N");
  EXPECT_FALSE(decode_gga(f));
  f.split("GPGGA,060845.00,4004.74005,X,11614.19613,E,1,10,0.85,53.5,M,,M,,");  // bad hemisphere
  EXPECT_FALSE(decode_gga(f));
  f.split("GPGGA,250845.00,4004.74005,N,11614.19613,E,1,10,0.85,53.5,M,,M,,");  // hour 25
  EXPECT_FALSE(decode_gga(f));
  f.split("GPGGA,060845.00,4064.74005,N,11614.19613,E,1,10,0.85,53.5,M,,M,,");  // 64 minutes
  EXPECT_FALSE(decode_gga(f));
  f.split("GPRMC,060845.00,A,4004.74005,N,11614.19613,E,0.000,,310217,,,A,V");  // 31 Feb
  EXPECT_FALSE(decode_rmc(f));
  f.split("GPGSV,3,1,11,3,82,133,50,6,70");  // a partial satellite block
  EXPECT_FALSE(decode_gsv(f));
}

// ------------------------------------------------------------------------------------------
// Random round trips: random values at the printed resolution survive encode -> frame -> decode.

class RoundTrip : public ::testing::Test {
 protected:
  std::mt19937_64 rng{0x6u};
  double uni(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  std::uint32_t uint(std::uint32_t lo, std::uint32_t hi) {
    return std::uniform_int_distribution<std::uint32_t>(lo, hi)(rng);
  }
  Real real(double lo, double hi, int decimals) {
    const double scale = std::pow(10.0, decimals);
    return {std::round(uni(lo, hi) * scale) / scale, decimals};
  }
  TimeOfDay tod(int decimals) {
    std::int64_t unit = 1'000'000'000;
    for (int i = 0; i < decimals; ++i) unit /= 10;
    return {static_cast<std::int64_t>(uint(0, 86'399'999)) * 1'000'000 / unit * unit, decimals};
  }
  LatLonField lat(int decimals) { return {uni(-89.9, 89.9), decimals}; }
  LatLonField lon(int decimals) { return {uni(-179.9, 179.9), decimals}; }
  template <class T>
  std::optional<Fields> reframe(const T& s, std::string& keep) {
    std::vector<std::uint8_t> out;
    if (!encode(s, out)) return std::nullopt;
    keep.assign(out.begin(), out.end());
    const auto fr = frame(keep.substr(0, keep.size() - 2));
    if (!fr) return std::nullopt;
    keep = fr->body;
    Fields f;
    f.split(keep);
    return f;
  }
  static void expect_latlon(const LatLonField& a, const LatLonField& b) {
    // Resolution: half a unit of the last printed minute decimal.
    EXPECT_NEAR(a.deg, b.deg, 0.5 * std::pow(10.0, -a.minute_decimals) / 60.0 + 1e-12);
  }
};

TEST_F(RoundTrip, Gga) {
  for (int i = 0; i < 300; ++i) {
    Gga s;
    s.talker = {'G', 'N'};
    s.time = tod(i % 2 ? 2 : 3);
    s.lat = lat(5 + i % 3);
    s.lon = lon(5 + i % 3);
    s.quality = (i % 3 == 0) ? 6 : 1;
    s.num_sats = Count{uint(0, 40), 1};
    s.hdop = real(0, 99.99, 2);
    s.height_m = real(-400, 9000, 1 + i % 3);
    if (i % 2) s.geoid_separation_m = real(-100, 100, 1);
    std::string keep;
    const auto f = reframe(s, keep);
    ASSERT_TRUE(f);
    const auto d = decode_gga(*f);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->time->ns, s.time->ns);
    expect_latlon(*s.lat, *d->lat);
    expect_latlon(*s.lon, *d->lon);
    EXPECT_EQ(d->quality, s.quality);
    EXPECT_EQ(d->num_sats->value, s.num_sats->value);
    EXPECT_DOUBLE_EQ(d->height_m->value, s.height_m->value);
    EXPECT_EQ(d->geoid_separation_m.has_value(), s.geoid_separation_m.has_value());
  }
}

TEST_F(RoundTrip, GllRmcVtgZdaGst) {
  for (int i = 0; i < 200; ++i) {
    std::string keep;
    Gll gll;
    gll.lat = lat(6);
    gll.lon = lon(6);
    gll.time = tod(2);
    gll.status = 'A';
    gll.mode = 'E';
    auto g = decode_gll(*reframe(gll, keep));
    ASSERT_TRUE(g);
    expect_latlon(*gll.lat, *g->lat);
    EXPECT_EQ(g->time->ns, gll.time->ns);
    EXPECT_EQ(*g->mode, 'E');

    Rmc rmc;
    rmc.dialect = i % 2 ? Dialect::kH30 : Dialect::kH51;
    rmc.time = tod(3);
    rmc.status = 'A';
    rmc.lat = lat(7);
    rmc.lon = lon(6);
    rmc.speed_knots = real(0, 200, 3);
    rmc.course_deg = real(0, 359.999, 3);
    rmc.date = Date{2000 + static_cast<int>(uint(0, 99)), static_cast<int>(uint(1, 12)), static_cast<int>(uint(1, 28))};
    rmc.mode = 'D';
    if (rmc.dialect == Dialect::kH51) rmc.nav_status = 'V';
    auto r = decode_rmc(*reframe(rmc, keep));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->dialect, rmc.dialect);
    EXPECT_EQ(r->date->year, rmc.date->year);
    EXPECT_EQ(r->date->month, rmc.date->month);
    EXPECT_EQ(r->date->day, rmc.date->day);
    EXPECT_DOUBLE_EQ(r->speed_knots->value, rmc.speed_knots->value);
    EXPECT_DOUBLE_EQ(r->course_deg->value, rmc.course_deg->value);

    Vtg vtg;
    vtg.course_true_deg = real(0, 359.999, 3);
    vtg.speed_knots = real(0, 100, 3);
    vtg.speed_kph = real(0, 185, 3);
    vtg.mode = 'N';
    auto v = decode_vtg(*reframe(vtg, keep));
    ASSERT_TRUE(v);
    EXPECT_DOUBLE_EQ(v->speed_kph->value, vtg.speed_kph->value);

    Zda zda;
    zda.time = tod(2);
    zda.day = Count{uint(1, 28), 2};
    zda.month = Count{uint(1, 12), 2};
    zda.year = Count{uint(2000, 2099), 4};
    zda.zone_hours = Count{0, 2};
    zda.zone_minutes = Count{0, 2};
    auto z = decode_zda(*reframe(zda, keep));
    ASSERT_TRUE(z);
    EXPECT_EQ(z->year->value, zda.year->value);
    EXPECT_EQ(z->time->ns, zda.time->ns);

    Gst gst;
    gst.time = tod(2);
    gst.range_rms_m = real(0, 100, 1);
    gst.std_lat_m = real(0, 50, 2);
    gst.std_lon_m = real(0, 50, 2);
    gst.std_alt_m = real(0, 50, 2);
    auto t = decode_gst(*reframe(gst, keep));
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(t->std_alt_m->value, gst.std_alt_m->value);
  }
}

TEST_F(RoundTrip, GsaGsv) {
  for (int i = 0; i < 200; ++i) {
    std::string keep;
    Gsa gsa;
    gsa.dialect = i % 2 ? Dialect::kH30 : Dialect::kH51;
    gsa.fix = uint(1, 3);
    const std::size_t used = uint(0, 12);
    for (std::size_t k = 0; k < used; ++k) gsa.sats[k] = Count{uint(1, 197), gsa.dialect == Dialect::kH51 ? 2 : 1};
    gsa.pdop = real(0, 99.99, 2);
    gsa.hdop = real(0, 99.99, 2);
    gsa.vdop = real(0, 99.99, 2);
    if (gsa.dialect == Dialect::kH51) gsa.system_id = Count{uint(1, 4), 1};
    auto a = decode_gsa(*reframe(gsa, keep));
    ASSERT_TRUE(a);
    EXPECT_EQ(a->dialect, gsa.dialect);
    for (std::size_t k = 0; k < kGsaSatSlots; ++k) {
      ASSERT_EQ(a->sats[k].has_value(), gsa.sats[k].has_value());
      if (gsa.sats[k]) {
        EXPECT_EQ(a->sats[k]->value, gsa.sats[k]->value);
      }
    }

    Gsv gsv;
    gsv.dialect = i % 2 ? Dialect::kH30 : Dialect::kH51;
    gsv.total_sentences = Count{uint(1, 9), 1};
    gsv.sentence_number = Count{uint(1, 9), 1};
    gsv.sats_in_view = Count{uint(0, 36), 1};
    gsv.sat_count = uint(1, 4);
    for (std::size_t k = 0; k < gsv.sat_count; ++k) {
      gsv.sats[k].number = Count{uint(1, 197), 2};
      gsv.sats[k].elevation_deg = Count{uint(0, 90), 2};
      if (k % 2) gsv.sats[k].azimuth_deg = Count{uint(0, 359), 3};
      gsv.sats[k].cn0_dbhz = Count{uint(0, 90), 2};
    }
    if (gsv.dialect == Dialect::kH51) gsv.signal_id = Count{0, 1};
    auto v = decode_gsv(*reframe(gsv, keep));
    ASSERT_TRUE(v);
    EXPECT_EQ(v->dialect, gsv.dialect);
    ASSERT_EQ(v->sat_count, gsv.sat_count);
    for (std::size_t k = 0; k < gsv.sat_count; ++k) {
      EXPECT_EQ(v->sats[k].number.value, gsv.sats[k].number.value);
      EXPECT_EQ(v->sats[k].azimuth_deg.has_value(), gsv.sats[k].azimuth_deg.has_value());
    }
  }
}

}  // namespace
}  // namespace navfuse::frontends::nmea
