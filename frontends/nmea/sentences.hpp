// Typed NMEA sentences as the UM220-INS writes them in its two dialects (Unicore INS protocol
// spec R2.8 §5.4, h51 L863-L1081, h30 L1085-L1273; digest §4.4), with decoders (Fields ->
// struct), encoders (struct -> sentence) and FrameRecord builders.
//
// Every numeric field keeps the decimals / zero padding it was printed with, so that decoding and
// re-encoding a sentence reproduces its bytes. Null fields are std::nullopt. Decoders return
// nullopt for a wrong field count or a malformed field; they do not judge plausibility beyond
// the field's documented range.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/nmea/fields.hpp"
#include "frontends/nmea/latlon.hpp"
#include "frontends/nmea/talker.hpp"
#include "frontends/nmea/utc_fields.hpp"
#include "frontends/nmea/writer.hpp"

namespace navfuse::frontends::nmea {

inline constexpr std::size_t kTalkerChars = 2;
inline constexpr std::size_t kSentenceTypeChars = 3;
inline constexpr double kMetresPerSecondPerKnot = 1852.0 / 3600.0;  // international knot
inline constexpr double kMetresPerSecondPerKph = 1000.0 / 3600.0;

// "GPGGA" -> talker GP, type "GGA" (upper-cased copy; names are case-insensitive, L154).
struct SentenceName {
  Talker talker{'G', 'P'};
  std::array<char, kSentenceTypeChars> type{};
  std::string_view type_view() const { return {type.data(), type.size()}; }
};
std::optional<SentenceName> split_sentence_name(std::string_view name);

// GGA fix quality FS (L880-L882, L1103).
enum class GgaQuality : std::uint8_t { kInvalid = 0, kPoint = 1, kDifferential = 2, kIns = 6 };

struct Gga {  // L863-L893 (h51), L1085-L1116 (h30)
  Talker talker{'G', 'P'};
  std::optional<TimeOfDay> time;
  std::optional<LatLonField> lat;
  std::optional<LatLonField> lon;
  std::uint32_t quality = 0;          // GgaQuality
  std::optional<Count> num_sats;
  std::optional<Real> hdop;
  // "msl": ELLIPSOID height with the default CFGGEOID=0 and Altref empty; MSL altitude with
  // Altref = geoid separation when CFGGEOID=1 (L885-L887, digest §11 item 18). Either way
  // height + separation (0 when empty) is the ellipsoidal height.
  std::optional<Real> height_m;
  bool height_unit = true;            // the first "M" (empty when not positioning)
  std::optional<Real> geoid_separation_m;
  std::optional<Real> diff_age_s;
  std::optional<Real> diff_station;
};

struct Gll {  // L895-L917, L1118-L1141
  Talker talker{'G', 'P'};
  std::optional<LatLonField> lat;
  std::optional<LatLonField> lon;
  std::optional<TimeOfDay> time;
  char status = 'V';               // A valid, V invalid
  std::optional<char> mode;        // h51: N/A/D/E; h30: V/A (L1138, digest §11 item 21)
};

inline constexpr std::size_t kGsaSatSlots = 12;
struct Gsa {  // L919-L946, L1143-L1166
  Talker talker{'G', 'P'};
  Dialect dialect = Dialect::kH51;  // from the field count: h51 adds systemID
  char selection_mode = 'A';        // M manual, A automatic
  std::uint32_t fix = 1;            // 1 none, 2 2D or INS, 3 3D (L934)
  std::array<std::optional<Count>, kGsaSatSlots> sats{};
  std::optional<Real> pdop, hdop, vdop;
  std::optional<Count> system_id;   // h51: 1 GPS, 2 GLONASS, 3 Galileo, 4 BDS (L939-L941)
};

inline constexpr std::size_t kGsvSatsPerSentence = 4;
struct GsvSat {
  Count number;                     // as printed; see sat_from_nmea()
  std::optional<Count> elevation_deg, azimuth_deg, cn0_dbhz;
};
struct Gsv {  // L948-L975, L1168-L1195
  Talker talker{'G', 'P'};
  Dialect dialect = Dialect::kH51;  // h51 adds signalID
  Count total_sentences, sentence_number, sats_in_view;
  std::array<GsvSat, kGsvSatsPerSentence> sats{};
  std::size_t sat_count = 0;        // 0..4: the last sentence of a group is short (digest §4.4.4)
  std::optional<Count> signal_id;   // h51, fixed 0 (L968)
};

struct Rmc {  // L977-L1007, L1197-L1226
  Talker talker{'G', 'P'};
  Dialect dialect = Dialect::kH51;  // h51 adds navStatus
  std::optional<TimeOfDay> time;
  char status = 'V';
  std::optional<LatLonField> lat;
  std::optional<LatLonField> lon;
  std::optional<Real> speed_knots;
  std::optional<Real> course_deg;   // clockwise from true north (vehicle front with CFGCOG 0)
  std::optional<Date> date;
  std::optional<Real> magnetic_variation_deg;
  std::optional<char> variation_direction;  // h51 null, h30 constant 'E' (L1224)
  std::optional<char> mode;         // N, A, D, E = INS (L1001-L1003)
  std::optional<char> nav_status;   // h51 fixed 'V' (L1004)
};

struct Vtg {  // L1009-L1032, L1228-L1252
  Talker talker{'G', 'P'};
  std::optional<Real> course_true_deg;
  std::optional<Real> course_magnetic_deg;
  std::optional<Real> speed_knots;
  std::optional<Real> speed_kph;
  std::optional<char> mode;
};

struct Zda {  // L1034-L1057, L1254-L1273
  Talker talker{'G', 'P'};
  std::optional<TimeOfDay> time;
  std::optional<Count> day, month, year;
  std::optional<Count> zone_hours, zone_minutes;  // fixed 00
};

struct Gst {  // L1059-L1081 (h51 only)
  Talker talker{'G', 'P'};
  std::optional<TimeOfDay> time;
  std::optional<Real> range_rms_m;
  std::optional<Real> std_major_m, std_minor_m, orientation_deg;  // null on the UM220
  std::optional<Real> std_lat_m, std_lon_m, std_alt_m;
};

struct Hdt {  // NMEA 0183 HDT (not a UM220 output)
  Talker talker{'G', 'P'};
  std::optional<Real> heading_deg;  // true heading, [0, 360)
};

// Decoders take the split fields of one sentence ([0] = name).
std::optional<Gga> decode_gga(const Fields& f);
std::optional<Gll> decode_gll(const Fields& f);
std::optional<Gsa> decode_gsa(const Fields& f);
std::optional<Gsv> decode_gsv(const Fields& f);
std::optional<Rmc> decode_rmc(const Fields& f);
std::optional<Vtg> decode_vtg(const Fields& f);
std::optional<Zda> decode_zda(const Fields& f);
std::optional<Gst> decode_gst(const Fields& f);
std::optional<Hdt> decode_hdt(const Fields& f);

// Encoders append one complete sentence; false (nothing appended) if it cannot be written
// (too long, non-finite value).
bool encode(const Gga& s, std::vector<std::uint8_t>& out);
bool encode(const Gll& s, std::vector<std::uint8_t>& out);
bool encode(const Gsa& s, std::vector<std::uint8_t>& out);
bool encode(const Gsv& s, std::vector<std::uint8_t>& out);
bool encode(const Rmc& s, std::vector<std::uint8_t>& out);
bool encode(const Vtg& s, std::vector<std::uint8_t>& out);
bool encode(const Zda& s, std::vector<std::uint8_t>& out);
bool encode(const Gst& s, std::vector<std::uint8_t>& out);
bool encode(const Hdt& s, std::vector<std::uint8_t>& out);

// FrameRecord fields, in wire order, with units in the names.
void append_fields(const Gga& s, frontends::FrameRecord& r);
void append_fields(const Gll& s, frontends::FrameRecord& r);
void append_fields(const Gsa& s, frontends::FrameRecord& r);
void append_fields(const Gsv& s, frontends::FrameRecord& r);
void append_fields(const Rmc& s, frontends::FrameRecord& r);
void append_fields(const Vtg& s, frontends::FrameRecord& r);
void append_fields(const Zda& s, frontends::FrameRecord& r);
void append_fields(const Gst& s, frontends::FrameRecord& r);

// Shared by the sentence files: begin "$<talker><type>".
void begin_sentence(SentenceWriter& w, Talker talker, std::string_view type);
// Optional-field writers: a null field is an empty one.
void add_optional(SentenceWriter& w, const std::optional<Real>& v);
void add_optional(SentenceWriter& w, const std::optional<Count>& v);
void add_optional(SentenceWriter& w, const std::optional<char>& v);
void add_optional(SentenceWriter& w, const std::optional<TimeOfDay>& v);
void add_optional_lat(SentenceWriter& w, const std::optional<LatLonField>& v);
void add_optional_lon(SentenceWriter& w, const std::optional<LatLonField>& v);
// Optional-field readers: true if the field is empty (v = nullopt) or parses; false if it is
// present but malformed.
bool read_optional(std::string_view field, std::optional<Real>& v);
bool read_optional(std::string_view field, std::optional<Count>& v);
bool read_optional(std::string_view field, std::optional<char>& v);
bool read_optional(std::string_view field, std::optional<TimeOfDay>& v);
// Latitude/longitude pair (value, hemisphere) at fields i and i+1.
bool read_optional_lat(const Fields& f, std::size_t i, std::optional<LatLonField>& v);
bool read_optional_lon(const Fields& f, std::size_t i, std::optional<LatLonField>& v);
// Record helpers for the shared field kinds.
void put_time(frontends::FrameRecord& r, const std::optional<TimeOfDay>& t);
void put_latlon(frontends::FrameRecord& r, const std::optional<LatLonField>& lat,
                const std::optional<LatLonField>& lon);

}  // namespace navfuse::frontends::nmea
