// Table-driven description of every MIP field layout the digest gives (data sets §4, aiding
// §5, commands §6-§7): parameter names with units, wire types, repeated groups and variants.
// One generic codec turns any described field into FrameRecord values (for `navfuse decode`) and
// back (for command building and round-trip tests). The measurement hot path does not use it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/bytes/byte_writer.hpp"
#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends::mip {

// Wire types (digest §2.4, L8835-8860); all big-endian.
enum class WireType : std::uint8_t {
  kU8, kS8, kBool, kU16, kS16, kU32, kS32, kU64, kF32, kF64,
  kVec3f,    // 3 floats, names suffixed _x/_y/_z
  kVec3d,    // 3 doubles
  kQuatf,    // 4 floats w, x, y, z
  kMat3f,    // 9 floats row-major m11..m33
  kChar16,   // fixed 16-character string
  kChar32,   // fixed 32-character string
  kBytes16,  // 16 opaque bytes, one u8 value each
};

struct Param {
  const char* name;
  WireType type;
  const char* unit = "";  // appended to the name: "lat" + "deg" -> "lat_deg"
};

struct FieldSchema {
  std::uint8_t set = 0;   // descriptor set (0xFF: shared descriptors, any data set)
  std::uint8_t desc = 0;  // field descriptor
  const char* name = "";
  std::span<const Param> params;
  // Index of the first parameter of a group repeated until the field ends (-1: none).
  int repeat_from = -1;
  // Variant selection: the schema applies only when data[variant_offset] == variant_value.
  int variant_offset = -1;
  std::uint8_t variant_value = 0;
  // Commands with a function selector (digest §2.6): params[0] is the selector; for selectors
  // other than Write only the first `key_params` parameters after it are sent.
  bool has_function = false;
  std::uint8_t key_params = 0;
};

// Lookup by set and descriptor (and, for variants, the field data). Data sets 0x92 and 0x94
// share 0x91's layouts (L5669-6359, L4824-4975); 0xD0-0xD8 resolve in any data set.
const FieldSchema* find_schema(std::uint8_t desc_set, std::uint8_t desc, std::span<const std::uint8_t> data);
std::span<const FieldSchema> data_schemas();
std::span<const FieldSchema> command_schemas();

// Number of scalar values a parameter expands to (vec3 -> 3, quat -> 4, mat -> 9, string -> 1).
std::size_t scalar_count(WireType t);
std::size_t wire_size(WireType t);
// Wire size of the non-repeated part; the size of one repeated group in *group_size.
std::size_t fixed_size(const FieldSchema& s, std::size_t* group_size = nullptr);

// Decodes `data` per schema into name/value pairs (appended). Trailing bytes beyond the
// described layout are ignored (digest §13.3: accept LEN >= expected). Returns false when the
// data is shorter than the fixed part. For a command whose selector is not Write only the key
// parameters are decoded.
bool decode_values(const FieldSchema& s, std::span<const std::uint8_t> data,
                   std::vector<std::pair<std::string, FieldValue>>& out);
// Encodes scalar values in the order decode_values produces them. Returns false on a count or
// type mismatch (nothing useful is written then).
bool encode_values(const FieldSchema& s, std::span<const FieldValue> values, bytes::BeWriter& w);

}  // namespace navfuse::frontends::mip
