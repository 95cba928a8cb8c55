#include "frontends/unicore/frontend.hpp"

#include "core/rotation/rotation.hpp"
#include "frontends/nmea/fields.hpp"
#include "frontends/nmea/framer.hpp"
#include "frontends/nmea/sentences.hpp"
#include "frontends/unicore/commands.hpp"
#include "frontends/unicore/commands_reply.hpp"
#include "frontends/unicore/decoder.hpp"
#include "frontends/unicore/encoder.hpp"

namespace navfuse::frontends::unicore {
namespace {

// Names that identify this device's stream. Plain NMEA names count too (the UM220 outputs them
// by default, L1479-L1486), but only with a checksum, so that other devices' '$' sentences
// (VectorNav "$VN...") or stray text do not look like a UM220.
constexpr std::string_view kUnicoreNames[] = {"GYOACC", "GYOACC-V", "SNRSTAT", "NAVPOS", "NAVVEL",
                                              "NAVTIME", "NAVACC", "NAVATT", "NOTICE", "CWOUT", "LSF"};
constexpr std::string_view kNmeaTypes[] = {"GGA", "GLL", "GSA", "GSV", "RMC", "VTG", "ZDA", "GST"};

bool known_name(std::string_view name) {
  for (std::string_view n : kUnicoreNames) {
    if (nmea::iequals(name, n)) return true;
  }
  if (const auto nm = nmea::split_sentence_name(name)) {
    for (std::string_view t : kNmeaTypes) {
      if (nm->type_view() == t) return true;
    }
  }
  return false;
}

std::size_t probe(std::span<const std::uint8_t> head) {
  nmea::SentenceFramer framer;
  std::size_t count = 0;
  framer.feed(head, [&](const nmea::Frame& f) {
    if (!f.has_checksum || f.start != '$') return;
    const std::string_view name = f.body.substr(0, f.body.find(','));
    if (known_name(name)) ++count;
  });
  return count;
}

std::unique_ptr<StreamDecoder> make_decoder() { return std::make_unique<UnicoreDecoder>(); }
std::unique_ptr<MeasurementEncoder> make_encoder() { return std::make_unique<UnicoreEncoder>(); }
// No installation geometry: the UM220-INS protocol has no lever-arm command (digest §1, "no
// lever-arm command"; spec R2.8 lists none), and its one installation command, CFGROTAT
// (L522-572), sets the module's own mounting angles to within 10 deg for its solution, which
// navfuse does not fuse (it rotates GYOACC by imu.mounting_rpy_deg itself).
std::vector<SetupStep> setup_steps(const config::Config&) {
  return steps_from_commands(commands_from_sentences(fusion_setup_commands()));
}

}  // namespace

const FrontendInfo& frontend() {
  static const FrontendInfo info{
      .format = "unicore",
      .description = "Unicore UM220-INS ASCII protocol + NMEA (GYOACC, NAVPOS/VEL/ATT, GGA...)",
      .probe = &probe,
      .make_decoder = &make_decoder,
      .make_encoder = &make_encoder,
      .default_profile = config::DeviceProfile::kUm220,
      .setup_steps = &setup_steps,
      .find_refusal = &find_refusal,
      // UM220-INS, automotive MEMS, 5 Hz solution: typical of the class, not datasheet guarantees.
      .device_errors = {.horizontal_std_m = 1.5,
                        .vertical_std_m = 3.0,
                        .velocity_std_mps = 0.1,
                        .roll_pitch_std_rad = 0.3 * rot::kDegToRad,
                        .heading_std_rad = 1.0 * rot::kDegToRad,
                        .outage_accel_std_mps2 = 0.03,
                        .rate_hz = 5.0},
  };
  return info;
}

}  // namespace navfuse::frontends::unicore
