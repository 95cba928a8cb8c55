#include "frontends/mip/frame_record.hpp"

#include <cstdio>

#include "frontends/mip/field_schema.hpp"
#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {
namespace {

std::string hex(std::span<const std::uint8_t> b) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s;
  s.reserve(b.size() * 2);
  for (std::uint8_t x : b) {
    s += kDigits[x >> 4];
    s += kDigits[x & 0xF];
  }
  return s;
}

std::string snake(const char* name) {
  std::string s(name);
  for (char& c : s)
    if (c == ' ' || c == '-' || c == '/' || c == '(' || c == ')') c = '_';
  return s;
}

}  // namespace

std::string_view set_name(std::uint8_t desc_set) {
  switch (desc_set) {
    case set::kBase: return "0x01 base command";
    case set::k3dm: return "0x0C 3dm command";
    case set::kFilterCmd: return "0x0D filter command";
    case set::kGnssCmd: return "0x0E gnss command";
    case set::kAiding: return "0x13 aiding command";
    case set::kSystemCmd: return "0x7F system command";
    case set::kSensor: return "0x80 sensor";
    case set::kFilter: return "0x82 filter";
    case set::kGnss1: return "0x91 gnss1";
    case set::kGnss2: return "0x92 gnss2";
    case set::kGnssCorrections: return "0x93 gnss corrections";
    case set::kGnssExternal: return "0x94 gnss external";
    case set::kSystem: return "0xA0 system";
    default: return "unknown";
  }
}

void build_frame_record(const PacketView& p, FrameRecord& rec) {
  rec.protocol = "mip";
  rec.name = set_name(p.desc_set);
  if (rec.name == "unknown") {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02X", p.desc_set);
    rec.name = buf;
  }
  rec.offset = p.offset;
  rec.fields.clear();
  FieldWalker walk(p.payload);
  FieldView f;
  std::vector<std::pair<std::string, FieldValue>> values;
  while (walk.next(f)) {
    const FieldSchema* s = find_schema(p.desc_set, f.desc, f.data);
    values.clear();
    std::string prefix;
    if (s != nullptr && decode_values(*s, f.data, values)) {
      prefix = snake(s->name) + ".";
    } else {
      char buf[16];
      std::snprintf(buf, sizeof buf, "0x%02X.", f.desc);
      prefix = buf;
      values.clear();
      values.emplace_back("raw_hex", hex(f.data));
    }
    for (auto& v : values) rec.fields.emplace_back(prefix + v.first, std::move(v.second));
  }
}

}  // namespace navfuse::frontends::mip
