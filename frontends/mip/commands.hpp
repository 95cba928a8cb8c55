// Building MIP command packets and reading replies (digest §2.5-§2.6, §7), to configure a real
// CV7 from navfuse. Every command goes through the layout tables (field_schema.hpp), so the
// bytes are those of the spec's own examples (tests/frontends/mip/examples_test.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "frontends/common/stream_decoder.hpp"
#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {

// One command field. `values` are the scalar parameters in table order (function selector first
// for settings commands); an empty list sends the bare descriptor (e.g. Ping `02 01`).
struct Command {
  std::uint8_t desc_set = 0;
  std::uint8_t desc = 0;
  std::vector<FieldValue> values;
};

// Encodes commands of one descriptor set into a single packet (several commands per packet are
// allowed within a set, L3850). nullopt when a command does not match its layout or the sets differ.
std::optional<std::vector<std::uint8_t>> build_command_packet(std::span<const Command> commands);
std::optional<std::vector<std::uint8_t>> build_command_packet(const Command& command);

// Common commands.
Command ping();                      // (0x01,0x01)
Command set_idle();                  // (0x01,0x02)
Command resume();                    // (0x01,0x06)
Command get_device_info();           // (0x01,0x03)
Command get_base_rate(std::uint8_t data_set);  // (0x0C,0x0E)
struct DescriptorRate {
  std::uint8_t descriptor;
  std::uint16_t decimation;  // base_rate / desired_rate (L1831)
};
Command message_format(std::uint8_t data_set, std::span<const DescriptorRate> fields);  // (0x0C,0x0F) write
Command stream_enable(std::uint8_t data_set, bool enable);                          // (0x0C,0x11) write
Command save_all_settings();                                                         // (0x0C,0x30) save
Command sensor_to_vehicle_euler(const Eigen::Vector3d& rpy_rad);                    // (0x0C,0x31) write
Command antenna_offset(std::uint8_t receiver_id, const Eigen::Vector3d& offset_m);  // (0x0D,0x54) write
Command speed_lever_arm(const Eigen::Vector3d& offset_m);  // (0x0D,0x61) write, source 1 ("must be 1", L8688)
// The Read (0x02) of a settings command: its function selector and first `key_params` parameters
// only (digest §2.6: other selectors than Write send only the key, e.g. the receiver id).
Command read_of(const Command& write, std::size_t key_params);
Command aiding_control(std::uint16_t aiding_source, bool enable);                    // (0x0D,0x50) write
Command reset_filter();                                                              // (0x0D,0x01)
Command run_filter();                                                                // (0x0D,0x05)
// (0x0D,0x52) write: automatic position, velocity and attitude (initial_cond_src 0) with the
// given heading-alignment sources (bit0 dual antenna, bit1 kinematic, bit2 mag, bit3 external).
Command filter_init_auto(std::uint8_t heading_alignment_bits);
Command gps_time_update(bool week, std::uint32_t value);  // (0x01,0x72) write

// What a fresh CV7 needs to stream for navfuse fusion: idle, formats (0x80 timestamp + delta
// theta/velocity at `imu_rate_hz`; 0x91 and 0x92 LLH, NED velocity, fix info at `gnss_rate_hz`;
// 0x82 status, LLH, velocity, Euler and uncertainties at `filter_rate_hz`), stream enables,
// resume. Decimations use the documented base rates (0x80/0x82 1 kHz, GNSS 5 Hz, L2686-2698);
// query (0x0C,0x0E) and pass the real ones when they differ.
struct SetupOptions {
  double imu_rate_hz = 100.0;
  double filter_rate_hz = 50.0;
  double gnss_rate_hz = 5.0;
  double sensor_base_rate_hz = 1000.0;
  double filter_base_rate_hz = 1000.0;
  double gnss_base_rate_hz = 5.0;
  bool second_receiver = true;
};
std::vector<std::vector<std::uint8_t>> cv7_setup_sequence(const SetupOptions& options = {});

// A reply packet's ACK/NACK fields, each with the response data that followed it (L3852).
struct ReplyEntry {
  std::uint8_t cmd_desc = 0;
  ReplyCode code = ReplyCode::kAck;
  std::optional<std::uint8_t> response_desc;
  std::vector<std::uint8_t> response_data;
};
// Parses a validated reply payload of a command set. Returns false on a malformed field walk.
bool parse_reply(std::span<const std::uint8_t> payload, std::vector<ReplyEntry>& out);
// Looks through the bytes a CV7 sent after a command for a NACK in a reply packet; returns a
// one-line description of the first one ("MIP NACK <code> for command (0xSS,0xDD)"), "" when none.
std::string find_refusal(std::span<const std::uint8_t> reply_bytes);

}  // namespace navfuse::frontends::mip
