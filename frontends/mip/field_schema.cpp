#include "frontends/mip/field_schema.hpp"

#include <cstring>

#include "core/bytes/byte_reader.hpp"
#include "frontends/mip/protocol.hpp"

namespace navfuse::frontends::mip {
namespace {

constexpr const char* kAxes3[] = {"x", "y", "z"};
constexpr const char* kQuat[] = {"w", "x", "y", "z"};
constexpr const char* kMat[] = {"m11", "m12", "m13", "m21", "m22", "m23", "m31", "m32", "m33"};

std::string scalar_name(const Param& p, std::size_t i, int group) {
  std::string n = p.name;
  switch (p.type) {
    case WireType::kVec3f:
    case WireType::kVec3d: n += '_'; n += kAxes3[i]; break;
    case WireType::kQuatf: n += '_'; n += kQuat[i]; break;
    case WireType::kMat3f: n += '_'; n += kMat[i]; break;
    case WireType::kBytes16: n += '_'; n += std::to_string(i); break;
    default: break;
  }
  if (p.unit[0] != '\0') {
    n += '_';
    n += p.unit;
  }
  if (group >= 0) {
    n += '[';
    n.append(std::to_string(group));
    n += ']';
  }
  return n;
}

bool is_command_desc_set(std::uint8_t s) { return set::is_command(s); }

// Parameters sent for a command's selector (digest §2.6: only Write carries the settings).
std::size_t active_params(const FieldSchema& s, std::span<const std::uint8_t> data) {
  if (!s.has_function || data.empty()) return s.params.size();
  if (data[0] == static_cast<std::uint8_t>(Function::kWrite)) return s.params.size();
  return std::min<std::size_t>(s.params.size(), 1u + s.key_params);
}

void read_scalars(const Param& p, bytes::BeReader& r, int group,
                  std::vector<std::pair<std::string, FieldValue>>& out) {
  switch (p.type) {
    case WireType::kU8: out.emplace_back(scalar_name(p, 0, group), std::uint64_t{r.u8()}); return;
    case WireType::kBool: out.emplace_back(scalar_name(p, 0, group), std::uint64_t{r.u8()}); return;
    case WireType::kS8: out.emplace_back(scalar_name(p, 0, group), std::int64_t{r.i8()}); return;
    case WireType::kU16: out.emplace_back(scalar_name(p, 0, group), std::uint64_t{r.u16()}); return;
    case WireType::kS16: out.emplace_back(scalar_name(p, 0, group), std::int64_t{r.i16()}); return;
    case WireType::kU32: out.emplace_back(scalar_name(p, 0, group), std::uint64_t{r.u32()}); return;
    case WireType::kS32: out.emplace_back(scalar_name(p, 0, group), std::int64_t{r.i32()}); return;
    case WireType::kU64: out.emplace_back(scalar_name(p, 0, group), std::uint64_t{r.u64()}); return;
    case WireType::kF32: out.emplace_back(scalar_name(p, 0, group), double{r.f32()}); return;
    case WireType::kF64: out.emplace_back(scalar_name(p, 0, group), r.f64()); return;
    case WireType::kVec3f:
    case WireType::kQuatf:
    case WireType::kMat3f:
      for (std::size_t i = 0; i < scalar_count(p.type); ++i)
        out.emplace_back(scalar_name(p, i, group), double{r.f32()});
      return;
    case WireType::kVec3d:
      for (std::size_t i = 0; i < 3; ++i) out.emplace_back(scalar_name(p, i, group), r.f64());
      return;
    case WireType::kBytes16:
      for (std::size_t i = 0; i < 16; ++i) out.emplace_back(scalar_name(p, i, group), std::uint64_t{r.u8()});
      return;
    case WireType::kChar16:
    case WireType::kChar32: {
      const auto raw = r.take(wire_size(p.type));
      std::string s(reinterpret_cast<const char*>(raw.data()), raw.size());
      const auto nul = s.find('\0');
      if (nul != std::string::npos) s.resize(nul);
      out.emplace_back(scalar_name(p, 0, group), std::move(s));
      return;
    }
  }
}

// Reads a FieldValue as the numeric type a wire type wants; false on a type mismatch.
template <typename T>
bool as_number(const FieldValue& v, T& out) {
  if (const auto* u = std::get_if<std::uint64_t>(&v)) { out = static_cast<T>(*u); return true; }
  if (const auto* i = std::get_if<std::int64_t>(&v)) { out = static_cast<T>(*i); return true; }
  if (const auto* d = std::get_if<double>(&v)) { out = static_cast<T>(*d); return true; }
  return false;
}

bool write_scalars(const Param& p, std::span<const FieldValue> v, bytes::BeWriter& w) {
  auto num = [&](std::size_t i, auto& x) { return as_number(v[i], x); };
  switch (p.type) {
    case WireType::kU8: case WireType::kBool: { std::uint8_t x; if (!num(0, x)) return false; w.u8(x); return true; }
    case WireType::kS8: { std::int8_t x; if (!num(0, x)) return false; w.i8(x); return true; }
    case WireType::kU16: { std::uint16_t x; if (!num(0, x)) return false; w.u16(x); return true; }
    case WireType::kS16: { std::int16_t x; if (!num(0, x)) return false; w.i16(x); return true; }
    case WireType::kU32: { std::uint32_t x; if (!num(0, x)) return false; w.u32(x); return true; }
    case WireType::kS32: { std::int32_t x; if (!num(0, x)) return false; w.i32(x); return true; }
    case WireType::kU64: { std::uint64_t x; if (!num(0, x)) return false; w.u64(x); return true; }
    case WireType::kF32: { float x; if (!num(0, x)) return false; w.f32(x); return true; }
    case WireType::kF64: { double x; if (!num(0, x)) return false; w.f64(x); return true; }
    case WireType::kVec3f: case WireType::kQuatf: case WireType::kMat3f:
      for (std::size_t i = 0; i < scalar_count(p.type); ++i) { float x; if (!num(i, x)) return false; w.f32(x); }
      return true;
    case WireType::kVec3d:
      for (std::size_t i = 0; i < 3; ++i) { double x; if (!num(i, x)) return false; w.f64(x); }
      return true;
    case WireType::kBytes16:
      for (std::size_t i = 0; i < 16; ++i) { std::uint8_t x; if (!num(i, x)) return false; w.u8(x); }
      return true;
    case WireType::kChar16: case WireType::kChar32: {
      const auto* s = std::get_if<std::string>(&v[0]);
      if (!s) return false;
      const std::size_t n = wire_size(p.type);
      for (std::size_t i = 0; i < n; ++i) w.u8(i < s->size() ? static_cast<std::uint8_t>((*s)[i]) : 0);
      return true;
    }
  }
  return false;
}

}  // namespace

std::size_t scalar_count(WireType t) {
  switch (t) {
    case WireType::kVec3f: case WireType::kVec3d: return 3;
    case WireType::kQuatf: return 4;
    case WireType::kMat3f: return 9;
    case WireType::kBytes16: return 16;
    default: return 1;
  }
}

std::size_t wire_size(WireType t) {
  switch (t) {
    case WireType::kU8: case WireType::kS8: case WireType::kBool: return 1;
    case WireType::kU16: case WireType::kS16: return 2;
    case WireType::kU32: case WireType::kS32: case WireType::kF32: return 4;
    case WireType::kU64: case WireType::kF64: return 8;
    case WireType::kVec3f: return 12;
    case WireType::kVec3d: return 24;
    case WireType::kQuatf: return 16;
    case WireType::kMat3f: return 36;
    case WireType::kChar16: case WireType::kBytes16: return 16;
    case WireType::kChar32: return 32;
  }
  return 0;
}

std::size_t fixed_size(const FieldSchema& s, std::size_t* group_size) {
  std::size_t fixed = 0, group = 0;
  for (std::size_t i = 0; i < s.params.size(); ++i) {
    if (s.repeat_from >= 0 && static_cast<int>(i) >= s.repeat_from) group += wire_size(s.params[i].type);
    else fixed += wire_size(s.params[i].type);
  }
  if (group_size) *group_size = group;
  return fixed;
}

const FieldSchema* find_schema(std::uint8_t desc_set, std::uint8_t desc, std::span<const std::uint8_t> data) {
  std::uint8_t s = desc_set;
  if (!is_command_desc_set(desc_set)) {
    if (shared::is_shared(desc)) s = set::kShared;
    else if (desc_set == set::kGnss2 || desc_set == set::kGnssExternal) s = set::kGnss1;
  }
  const auto table = is_command_desc_set(desc_set) ? command_schemas() : data_schemas();
  for (const auto& f : table) {
    if (f.set != s || f.desc != desc) continue;
    if (f.variant_offset >= 0) {
      const auto off = static_cast<std::size_t>(f.variant_offset);
      if (off >= data.size() || data[off] != f.variant_value) continue;
    }
    return &f;
  }
  // The ACK/NACK field is the same in every command set (L8862-8870).
  if (is_command_desc_set(desc_set) && desc == kAckNackDescriptor) {
    for (const auto& f : table)
      if (f.set == 0 && f.desc == kAckNackDescriptor) return &f;
  }
  return nullptr;
}

bool decode_values(const FieldSchema& s, std::span<const std::uint8_t> data,
                   std::vector<std::pair<std::string, FieldValue>>& out) {
  const std::size_t n_params = active_params(s, data);
  bytes::BeReader r(data);
  const std::size_t fixed_end = s.repeat_from >= 0 ? std::min<std::size_t>(n_params, static_cast<std::size_t>(s.repeat_from)) : n_params;
  for (std::size_t i = 0; i < fixed_end; ++i) {
    if (r.remaining() < wire_size(s.params[i].type)) return false;
    read_scalars(s.params[i], r, -1, out);
  }
  if (s.repeat_from >= 0 && n_params > static_cast<std::size_t>(s.repeat_from)) {
    std::size_t group = 0;
    fixed_size(s, &group);
    for (int g = 0; group > 0 && r.remaining() >= group; ++g)
      for (std::size_t i = static_cast<std::size_t>(s.repeat_from); i < s.params.size(); ++i)
        read_scalars(s.params[i], r, g, out);
  }
  return r.ok();
}

bool encode_values(const FieldSchema& s, std::span<const FieldValue> values, bytes::BeWriter& w) {
  std::size_t n_params = s.params.size();
  if (s.has_function && !values.empty()) {
    std::uint8_t fn = 0;
    if (!as_number(values[0], fn)) return false;
    if (fn != static_cast<std::uint8_t>(Function::kWrite)) n_params = std::min<std::size_t>(n_params, 1u + s.key_params);
  }
  std::size_t vi = 0;
  const std::size_t fixed_end = s.repeat_from >= 0 ? std::min<std::size_t>(n_params, static_cast<std::size_t>(s.repeat_from)) : n_params;
  auto put = [&](const Param& p) {
    const std::size_t k = scalar_count(p.type);
    if (vi + k > values.size()) return false;
    if (!write_scalars(p, values.subspan(vi, k), w)) return false;
    vi += k;
    return true;
  };
  for (std::size_t i = 0; i < fixed_end; ++i)
    if (!put(s.params[i])) return false;
  if (s.repeat_from >= 0 && n_params > static_cast<std::size_t>(s.repeat_from)) {
    while (vi < values.size())
      for (std::size_t i = static_cast<std::size_t>(s.repeat_from); i < s.params.size(); ++i)
        if (!put(s.params[i])) return false;
  }
  return vi == values.size();
}

}  // namespace navfuse::frontends::mip
