// Every MIP packet printed in the digest §11.1 (spec line numbers in the names) and the derived
// vectors of §11.4: the 41 whose checksum verifies are framed, decode to the values the digest
// states, and re-encode through the layout tables to identical bytes; the two broken ones
// (errata E2 checksum, E4 malformed hex) are rejected and their corrected versions accepted.
#include <gtest/gtest.h>

#include <cmath>

#include "frontends/mip/commands.hpp"
#include "frontends/mip/field_schema.hpp"
#include "frontends/mip/frame_record.hpp"
#include "frontends/mip/framer.hpp"
#include "frontends/mip/writer.hpp"
#include "tests/frontends/mip/test_util.hpp"

namespace navfuse::frontends::mip {
namespace {

using test::field;
using test::hex;

struct Expect {
  const char* name;
  double value;  // NaN: the value must be NaN
  int nth = 0;
};
struct Example {
  const char* line;
  const char* hex;
  std::vector<Expect> expect;
};

const double kNaN = std::nan("");

// Values as the digest §11.1 "Decoded meaning" column and §11.3 state them.
const std::vector<Example> kVerified = {
    {"L3822", "75 65 80 0E 0E 03 3E7A63A0 BB8E3B29 7FE5BF7F 83 E1", {}},
    {"L3836", "75 65 80 0E 0E 06 3E7A63A0 BB8E3B29 7FE5BF7F 86 08",
     {{"scaled_mag.mag_x_gauss", 0.24452066}, {"scaled_mag.mag_y_gauss", -0.0043405485}, {"scaled_mag.mag_z_gauss", kNaN}}},
    {"L3901", "75650102 0201 E0C6", {}},
    {"L3913", "75 65 01 04 04 F1 01 00 D5 6A", {{"ack_nack.cmd_descriptor", 0x01}, {"ack_nack.reply_code", 0}}},
    {"L3919", "75650C03 030E80 7A7E", {{"get_data_base_rate.desc_set", 0x80}}},
    {"L3921", "75650C09 04F10E00 058E8003E8 F058",
     {{"ack_nack.cmd_descriptor", 0x0E}, {"ack_nack.reply_code", 0}, {"data_base_rate.desc_set", 0x80}, {"data_base_rate.rate_hz", 1000}}},
    {"L3929a", "75650c04 04280104 1b55", {{"pps_source.function", 1}, {"pps_source.source", 4}}},
    {"L3929b", "75650C04 04F12800 07FA", {{"ack_nack.cmd_descriptor", 0x28}, {"ack_nack.reply_code", 0}}},
    {"L3933", "75650C03 032803 1735", {{"pps_source.function", 3}}},
    {"L3935", "75650C04 04280100 1751", {{"pps_source.function", 1}, {"pps_source.source", 0}}},
    // Errata E3: printed as "LOAD", but the bytes are an ACK-shaped field (cmd 0x28, code 0x04).
    {"L3937", "75650c04 04f12804 0bfe", {{"ack_nack.cmd_descriptor", 0x28}, {"ack_nack.reply_code", 4}}},
    {"L3941a", "75650C09 032805 032803 032802 7A4A",
     {{"pps_source.function", 5, 0}, {"pps_source.function", 3, 1}, {"pps_source.function", 2, 2}}},
    {"L3941b", "75650C0F 04F12800 04F12800 04F12800 03A801 F8D9",
     {{"ack_nack.cmd_descriptor", 0x28, 2}, {"ack_nack.reply_code", 0, 2}, {"pps_source.source", 1}}},
    {"L3957", "7565 800E 0E04 3E7A 63A0 BB8E 3B29 7FE5 BF7F 84EE",
     {{"scaled_accel.accel_x_g", 0.24452066}, {"scaled_accel.accel_y_g", -0.0043405485}, {"scaled_accel.accel_z_g", kNaN}}},
    {"L3060", "75650c07 07410101040204 4171",
     {{"gpio_config.pin", 1}, {"gpio_config.feature", 4}, {"gpio_config.behavior", 2}, {"gpio_config.pin_mode", 4}}},
    {"L3079", "75650c07 072e0101010104 2af4",
     {{"event_trigger_gpio.instance", 1}, {"event_trigger_gpio.type", 1}, {"event_trigger_gpio.pin", 1}, {"event_trigger_gpio.mode", 4}}},
    {"L3102", "75650c0f 0f2f0101010280000005d0d5d60708 47ca",
     {{"event_action_message.instance", 1}, {"event_action_message.trigger_id", 1}, {"event_action_message.desc_set", 0x80},
      {"event_action_message.decimation", 0}, {"event_action_message.num_fields", 5}, {"event_action_message.descriptor[0]", 0xD0},
      {"event_action_message.descriptor[1]", 0xD5}, {"event_action_message.descriptor[2]", 0xD6},
      {"event_action_message.descriptor[3]", 0x07}, {"event_action_message.descriptor[4]", 0x08}}},
    {"L3118", "75650c0e 0e2f0102010282000004d0d5d605 3d7a",
     {{"event_action_message.instance", 2}, {"event_action_message.desc_set", 0x82}, {"event_action_message.num_fields", 4},
      {"event_action_message.descriptor[3]", 0x05}}},
    {"L3133", "75650c05 052b010101 1e82", {{"event_control.instance", 1}, {"event_control.mode", 1}}},
    {"L3174", "75650c07 07410101010200 3a64",
     {{"gpio_config.pin", 1}, {"gpio_config.feature", 1}, {"gpio_config.behavior", 2}, {"gpio_config.pin_mode", 0}}},
    {"L3194", "75650c08 082f010101010101 2b31",
     {{"event_action_gpio.instance", 1}, {"event_action_gpio.trigger_id", 1}, {"event_action_gpio.type", 1},
      {"event_action_gpio.pin", 1}, {"event_action_gpio.mode", 1}}},
    // Errata E6: the printed command bytes (L3214) are wrong; the packet is trusted.
    {"L3216", "75650c19 192e01010280d50102415fca0540000000416fca0560000000 308a",
     {{"event_trigger_threshold.instance", 1}, {"event_trigger_threshold.desc_set", 0x80},
      {"event_trigger_threshold.field_desc", 0xD5}, {"event_trigger_threshold.param_id", 1},
      {"event_trigger_threshold.threshold_type", 2}, {"event_trigger_threshold.low_or_int_thres", 8333333.0},
      {"event_trigger_threshold.high_thres_or_interval", 16666667.0}}},
    {"L3273", "75650c07 072e0101010302 2af6", {{"event_trigger_gpio.pin", 3}, {"event_trigger_gpio.mode", 2}}},
    {"L3287", "75650c07 07410103010104 3f6e",
     {{"gpio_config.pin", 3}, {"gpio_config.feature", 1}, {"gpio_config.behavior", 1}, {"gpio_config.pin_mode", 4}}},
    {"L3314", "75650c04 042c0101 1c5e", {{"get_event_trigger_status.requested_count", 1}, {"get_event_trigger_status.instance[0]", 1}}},
    // Errata E17: status is a bitfield, 0x02 = enabled.
    {"L3316", "75650c09 04f12c00 05b6010102 cf63",
     {{"ack_nack.cmd_descriptor", 0x2C}, {"event_trigger_status.count", 1}, {"event_trigger_status.type[0]", 1},
      {"event_trigger_status.status[0]", 2}}},
    {"L3326", "75650c09 04f12c00 05b6010103 d064", {{"event_trigger_status.status[0]", 3}}},
    {"L3355", "75650c0c 0c2f0101010280000a020405 c778",
     {{"event_action_message.desc_set", 0x80}, {"event_action_message.decimation", 10},
      {"event_action_message.descriptor[0]", 0x04}, {"event_action_message.descriptor[1]", 0x05}}},
    {"L3372", "75650c0b 0b2f0102010282000a0105 c3ab",
     {{"event_action_message.instance", 2}, {"event_action_message.desc_set", 0x82}, {"event_action_message.decimation", 10},
      {"event_action_message.descriptor[0]", 0x05}}},
    {"L3416", "75650c07 07410104010200 3d70", {{"gpio_config.pin", 4}, {"gpio_config.behavior", 2}}},
    {"L3430", "75650c05 0542010401 38e4", {{"gpio_state.pin", 4}, {"gpio_state.state", 1}}},
    {"L3440", "75650c05 0542010400 37e3", {{"gpio_state.pin", 4}, {"gpio_state.state", 0}}},
    {"L3458", "75650c08 082f010101010405 323b", {{"event_action_gpio.pin", 4}, {"event_action_gpio.mode", 5}}},
    {"L3479", "75650c19 192e010102800c01013fe921fb323ae5afbfe921fb323ae5af e040",
     {{"event_trigger_threshold.field_desc", 0x0C}, {"event_trigger_threshold.param_id", 1},
      {"event_trigger_threshold.threshold_type", 1}, {"event_trigger_threshold.low_or_int_thres", 0.7853981},
      {"event_trigger_threshold.high_thres_or_interval", -0.7853981}}},
    {"L3559", "75650c19 192e010202800c02013fe921fb323ae5afbfe921fb323ae5af e268",
     {{"event_trigger_threshold.instance", 2}, {"event_trigger_threshold.param_id", 2}}},
    {"L3571", "75650c05 052b010201 1f84", {{"event_control.instance", 2}, {"event_control.mode", 1}}},
    {"L3602", "75650c05 052b010301 2086", {{"event_control.instance", 3}, {"event_control.mode", 1}}},
    // Errata E5: labelled ONESHOT_HIGH, the bytes say ACTIVE_HIGH (1); the bytes are trusted.
    {"L3620", "75650c08 082f010103010401 303f",
     {{"event_action_gpio.trigger_id", 3}, {"event_action_gpio.pin", 4}, {"event_action_gpio.mode", 1}}},
    {"L3671", "75650c19 192e010202800c0101bfc6571814c9bba03fc6571814c9bba0 b1fa",
     {{"event_trigger_threshold.low_or_int_thres", -0.1745329}, {"event_trigger_threshold.high_thres_or_interval", 0.1745329}}},
    {"L3721", "75650c0b 0b2e010303cece03010200 d3e9",
     {{"event_trigger_combination.instance", 3}, {"event_trigger_combination.logic_table", 0xCECE},
      {"event_trigger_combination.input_a", 3}, {"event_trigger_combination.input_b", 1},
      {"event_trigger_combination.input_c", 2}, {"event_trigger_combination.input_d", 0}}},
    {"L3761", "75650c08 082f010202010406 3545",
     {{"event_action_gpio.instance", 2}, {"event_action_gpio.trigger_id", 2}, {"event_action_gpio.mode", 6}}},
};

// Corrected packets (digest §11.1 / §11.4, errata E2-E4).
const std::vector<Example> kCorrected = {
    {"L3846 corrected (E2)", "7565801C0E053E7A63A0BB8E3B297FE5BF7F0E063E7A63A0BB8E3B297FE5BF7FB11E",
     {{"scaled_gyro.gyro_x_radps", 0.24452066}, {"scaled_mag.mag_y_gauss", -0.0043405485}}},
    {"L3937 intended LOAD (E3)", "75650C03 032804 1836", {{"pps_source.function", 4}}},
    {"L3590 corrected (E4)", "75650C0B 0B2E010303FFFF01020000 32FB",
     {{"event_trigger_combination.instance", 3}, {"event_trigger_combination.logic_table", 0xFFFF},
      {"event_trigger_combination.input_a", 1}, {"event_trigger_combination.input_b", 2}}},
    {"§11.4 idle", "756501020202E1C7", {}},
    {"§11.4 device info", "756501020203E2C8", {}},
    {"§11.4 resume", "756501020206E5CB", {}},
    {"§11.4 reset filter", "75650D020201ECF6", {}},
    {"§11.4 run filter", "75650D020205F0FA", {}},
    {"§11.4 save all", "75650C030330031F45", {{"device_startup_settings.function", 3}}},
    {"§11.4 message format 0x82", "75650C14140F018205D3000A01000A02000A05000A10000AC28F",
     {{"message_format.desc_set", 0x82}, {"message_format.num_descriptors", 5}, {"message_format.descriptor[0]", 0xD3},
      {"message_format.decimation[4]", 10}, {"message_format.descriptor[4]", 0x10}}},
    {"§11.4 time update tow", "756501080872010200054600AB2E", {{"gps_time_update.field_id", 2}, {"gps_time_update.value", 345600}}},
    {"§11.4 time update week", "7565010808720101000008FC639A", {{"gps_time_update.field_id", 1}, {"gps_time_update.value", 2300}}},
    {"§11.4 frame config", "7565131E1E0101010101BEA3D70A3DE147AEBF23D70A00000000000000000000000046A1",
     {{"aiding_frame_config_euler.frame_id", 1}, {"aiding_frame_config_euler.translation_x_m", -0.32},
      {"aiding_frame_config_euler.translation_y_m", 0.11}, {"aiding_frame_config_euler.translation_z_m", -0.64}}},
    {"§11.4 body velocity", "75651327272A0101000000000002693002406FAE1400000000000000003DF5C28F3DF5C28F3DF5C28F000301C7",
     {{"body_frame_velocity_aiding.time_ns", 158000}, {"body_frame_velocity_aiding.frame_id", 2},
      {"body_frame_velocity_aiding.velocity_x_mps", 3.745}, {"body_frame_velocity_aiding.std_y_mps", 0.12},
      {"body_frame_velocity_aiding.valid_flags", 3}}},
    {"§11.4 magnetic field", "75651327273201010000000000026930033EE6E9793EB0A3D73ECD4FDF3CFDF3B63CFDF3B63CFDF3B60007E110",
     {{"magnetic_field_aiding.frame_id", 3}, {"magnetic_field_aiding.field_x_gauss", 0.451},
      {"magnetic_field_aiding.field_z_gauss", 0.401}, {"magnetic_field_aiding.std_x_gauss", 0.031}}},
};

// Frames `bytes`, expecting exactly one valid packet; returns its record and re-encoded bytes.
void check_example(const Example& ex) {
  SCOPED_TRACE(ex.line);
  const auto bytes = hex(ex.hex);
  Framer framer;
  std::vector<PacketView> packets;
  framer.feed(bytes, [&](const PacketView& p) { packets.push_back(p); });
  ASSERT_EQ(packets.size(), 1u);
  EXPECT_EQ(framer.counters().bad_frames, 0u);
  EXPECT_EQ(framer.counters().skipped_bytes, 0u);
  FrameRecord rec;
  build_frame_record(packets[0], rec);
  for (const auto& e : ex.expect) {
    const auto v = field(rec, e.name, e.nth);
    ASSERT_TRUE(v.has_value()) << e.name;
    if (std::isnan(e.value)) {
      EXPECT_TRUE(std::isnan(*v)) << e.name;
    } else {
      EXPECT_NEAR(*v, e.value, 1e-7 * std::max(1.0, std::abs(e.value))) << e.name;
    }
  }
  // Re-encode every field from its decoded values through the same tables.
  std::vector<std::uint8_t> out;
  PacketWriter w(out, packets[0].desc_set);
  FieldWalker walk(packets[0].payload);
  FieldView f;
  while (walk.next(f)) {
    const FieldSchema* s = find_schema(packets[0].desc_set, f.desc, f.data);
    std::vector<std::pair<std::string, FieldValue>> named;
    if (s == nullptr || !decode_values(*s, f.data, named)) {
      w.raw_field(f.desc, f.data);  // e.g. L3822's generic descriptor 0x03 (errata E43)
      continue;
    }
    std::vector<FieldValue> values;
    for (auto& nv : named) values.push_back(nv.second);
    ASSERT_TRUE(encode_values(*s, values, w.field(f.desc))) << s->name;
  }
  w.finish();
  EXPECT_EQ(out, bytes);
}

TEST(MipExamples, FortyOneVerifyingPacketsDecodeAndReencode) {
  ASSERT_EQ(kVerified.size(), 41u);
  for (const auto& ex : kVerified) check_example(ex);
}

TEST(MipExamples, CorrectedAndDerivedPacketsDecodeAndReencode) {
  for (const auto& ex : kCorrected) check_example(ex);
}

TEST(MipExamples, WrongChecksumOfL3846IsRejected) {
  // Errata E2: the printed checksum E0 C6 is the Ping's; B1 1E is correct.
  const auto bytes = hex("75 65 80 1C 0E 05 3E7A63A0 BB8E3B29 7FE5BF7F 0E 06 3E7A63A0 BB8E3B29 7FE5BF7F E0 C6");
  Framer framer;
  int n = 0;
  framer.feed(bytes, [&](const PacketView&) { ++n; });
  framer.finish([&](const PacketView&) { ++n; });
  EXPECT_EQ(n, 0);
  EXPECT_EQ(framer.counters().bad_frames, 1u);
  EXPECT_EQ(framer.counters().skipped_bytes, bytes.size());
}

TEST(MipExamples, MalformedL3590IsRejected) {
  // Errata E4: an odd number of hex digits (stray "e0"); whatever bytes it is read as, it fails.
  const auto bytes = hex("75650c0b 0b2e010303ffffe01020000 31f6");
  Framer framer;
  int n = 0;
  framer.feed(bytes, [&](const PacketView&) { ++n; });
  framer.finish([&](const PacketView&) { ++n; });
  EXPECT_EQ(n, 0);
  EXPECT_EQ(framer.counters().frames, 0u);
}

TEST(MipExamples, BuildersReproduceDerivedCommandBytes) {
  auto eq = [](const Command& c, const char* expected) {
    const auto p = build_command_packet(c);
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(*p, hex(expected));
  };
  eq(ping(), "75650102 0201 E0C6");
  eq(set_idle(), "756501020202E1C7");
  eq(get_device_info(), "756501020203E2C8");
  eq(resume(), "756501020206E5CB");
  eq(reset_filter(), "75650D020201ECF6");
  eq(run_filter(), "75650D020205F0FA");
  eq(save_all_settings(), "75650C030330031F45");
  eq(get_base_rate(0x80), "75650C03 030E80 7A7E");
  eq(gps_time_update(false, 345600), "756501080872010200054600AB2E");
  eq(gps_time_update(true, 2300), "7565010808720101000008FC639A");
  const DescriptorRate f[] = {{0xD3, 10}, {0x01, 10}, {0x02, 10}, {0x05, 10}, {0x10, 10}};
  eq(message_format(0x82, f), "75650C14140F018205D3000A01000A02000A05000A10000AC28F");
  // Three PPS commands in one packet (L3941).
  const Command pps[] = {{0x0C, 0x28, {std::uint64_t{5}}}, {0x0C, 0x28, {std::uint64_t{3}}}, {0x0C, 0x28, {std::uint64_t{2}}}};
  const auto multi = build_command_packet(pps);
  ASSERT_TRUE(multi.has_value());
  EXPECT_EQ(*multi, hex("75650C09 032805 032803 032802 7A4A"));
}

}  // namespace
}  // namespace navfuse::frontends::mip
