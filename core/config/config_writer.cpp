// to_yaml(): the effective configuration, printed from the key table so that every key appears
// exactly once, grouped under its section, with its meaning as a comment. The output is valid
// input for load_from_string() and reads back to an equal Config (shortest round-trip numbers,
// std::to_chars, C++17 [charconv]).
#include <charconv>
#include <string>
#include <vector>

#include "core/config/config.hpp"

namespace navfuse::config {
namespace {

std::string format_number(double v) {
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, result.ptr);
}

std::string format_vec3(const Vec3& v) {
  // Appended piecewise: `"[" + std::string` trips GCC 12's false -Wrestrict (GCC bug 105329).
  std::string out = "[";
  out += format_number(v[0]) + ", " + format_number(v[1]) + ", " + format_number(v[2]);
  out += ']';
  return out;
}

std::vector<std::string_view> split(std::string_view path) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

}  // namespace

std::string to_yaml(const Config& config) {
  Config copy = config;  // the table's accessors take a mutable Config
  std::string out = "device: " + std::string(to_string(config.device)) +
                    "  # cv7 | vn300 | um220 | fusionengine | generic\n";
  std::vector<std::string_view> open;  // sections currently printed, outermost first
  for (const KeyBinding& binding : key_table()) {
    const std::vector<std::string_view> parts = split(binding.key);
    const std::size_t depth = parts.size() - 1;
    std::size_t common = 0;
    while (common < open.size() && common < depth && open[common] == parts[common]) ++common;
    open.resize(common);
    for (std::size_t level = common; level < depth; ++level) {
      out += std::string(2 * level, ' ') + std::string(parts[level]) + ":\n";
      open.push_back(parts[level]);
    }
    out += std::string(2 * depth, ' ') + std::string(parts.back()) + ": ";
    if (auto scalar = std::get_if<double* (*)(Config&)>(&binding.target)) {
      out += format_number(*(*scalar)(copy));
    } else if (auto optional = std::get_if<std::optional<double>* (*)(Config&)>(&binding.target)) {
      const std::optional<double>& v = *(*optional)(copy);
      out += v ? format_number(*v) : std::string("~");
    } else if (auto flag = std::get_if<bool* (*)(Config&)>(&binding.target)) {
      out += *(*flag)(copy) ? "true" : "false";
    } else if (auto optional_flag = std::get_if<std::optional<bool>* (*)(Config&)>(&binding.target)) {
      const std::optional<bool>& v = *(*optional_flag)(copy);
      out += v ? (*v ? "true" : "false") : "~";
    } else if (auto platform = std::get_if<Platform* (*)(Config&)>(&binding.target)) {
      out += to_string(*(*platform)(copy));
    } else if (auto optional_vec = std::get_if<std::optional<Vec3>* (*)(Config&)>(&binding.target)) {
      const std::optional<Vec3>& v = *(*optional_vec)(copy);
      out += v ? format_vec3(*v) : std::string("~");
    } else {
      out += format_vec3(*std::get<Vec3* (*)(Config&)>(binding.target)(copy));
    }
    out += "  # " + std::string(binding.help) + "\n";
  }
  return out;
}

}  // namespace navfuse::config
