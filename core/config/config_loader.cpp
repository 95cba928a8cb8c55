// Loading a Config from YAML (yaml-cpp), strictly: every key must be in the key table
// (config_keys.cpp), every value must have the right type, length and sign, and the first problem
// found is thrown as one line naming the source, the dotted key and what was wrong, e.g.
//   config.yaml: imu.gyro_arw_deg_rthr: expected a number, got "fast" (line 3)
//   config.yaml: unknown key 'imu.gyro_arw' (line 3); did you mean 'imu.gyro_arw_deg_rthr'?
// DESIGN.md: "A setting the engine does not know is an error that names the key, not a silent
// default."
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "core/config/config.hpp"

namespace navfuse::config {
namespace {

std::string line_of(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return "";
  return " (line " + std::to_string(mark.line + 1) + ")";  // yaml-cpp lines are 0-based
}

// How a value that was not what we wanted looks, for "expected X, got Y".
std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "nothing";
    case YAML::NodeType::Scalar:
      return "\"" + node.Scalar() + "\"";
    case YAML::NodeType::Sequence:
      return "a list of " + std::to_string(node.size());
    case YAML::NodeType::Map:
      return "a mapping";
    case YAML::NodeType::Undefined:
      break;
  }
  return "an undefined value";
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Levenshtein distance, one row at a time.
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Every path a YAML file may contain: "device", each section ("imu", ...) and each key.
struct KnownPaths {
  std::set<std::string, std::less<>> keys;
  std::set<std::string, std::less<>> sections;

  KnownPaths() {
    keys.insert("device");
    for (const KeyBinding& b : key_table()) {
      keys.insert(std::string(b.key));
      for (std::size_t dot = b.key.find('.'); dot != std::string_view::npos;
           dot = b.key.find('.', dot + 1)) {
        sections.insert(std::string(b.key.substr(0, dot)));
      }
    }
  }

  // The known path closest to a misspelt one, or "" when nothing is plausibly meant.
  std::string closest(std::string_view unknown) const {
    std::string best;
    std::size_t best_score = std::max<std::size_t>(3, unknown.size() / 2) + 1;
    auto consider = [&](const std::string& candidate) {
      std::size_t score = edit_distance(unknown, candidate);
      // A truncated key ("imu.gyro_arw") is far from the full one by edit distance alone.
      if (candidate.starts_with(unknown)) score = std::min<std::size_t>(score, 1);
      if (score < best_score) {
        best_score = score;
        best = candidate;
      }
    };
    for (const auto& k : keys) consider(k);
    for (const auto& s : sections) consider(s);
    return best;
  }
};

const KnownPaths& known_paths() {
  static const KnownPaths paths;
  return paths;
}

class Loader {
 public:
  explicit Loader(std::string source) : source_(std::move(source)) {}

  Config load(const std::string& text) {
    YAML::Node root;
    try {
      root = YAML::Load(text);
    } catch (const YAML::ParserException& e) {
      throw ConfigError(source_ + ":" + std::to_string(e.mark.line + 1) + ":" +
                        std::to_string(e.mark.column + 1) + ": invalid YAML: " + e.msg);
    }
    // An empty (or comment-only) file is more likely a wrong or truncated file than a wish for
    // the generic defaults; omitting --config gives the device profile's defaults.
    if (root.IsNull()) throw ConfigError(source_ + ": empty configuration: give at least `device:`");
    if (!root.IsMap()) {
      throw ConfigError(source_ + ": expected a mapping of keys at the top level, got " +
                        describe(root) + line_of(root));
    }
    // `device` first: it chooses the defaults every other key then overrides.
    Config config = defaults_for(DeviceProfile::kGeneric);
    if (const YAML::Node device = root["device"]; device) config = defaults_for(profile(device));
    walk(root, "", config);
    return config;
  }

 private:
  [[noreturn]] void fail(const YAML::Node& at, std::string_view key, const std::string& what) {
    throw ConfigError(source_ + ": " + std::string(key) + ": " + what + line_of(at));
  }

  DeviceProfile profile(const YAML::Node& node) {
    if (node.IsScalar()) {
      if (auto p = device_profile_from_string(node.Scalar())) return *p;
    }
    fail(node, "device",
         "expected one of cv7, vn300, um220, fusionengine, generic, got " + describe(node));
  }

  void walk(const YAML::Node& map, const std::string& prefix, Config& config) {
    std::set<std::string> seen;
    for (const auto& entry : map) {
      if (!entry.first.IsScalar()) {
        fail(entry.first, prefix.empty() ? "<top level>" : prefix,
             "expected a key name, got " + describe(entry.first));
      }
      const std::string path = prefix + entry.first.Scalar();
      if (!seen.insert(path).second) fail(entry.first, path, "duplicate key");
      if (path == "device") continue;  // applied first, in load()

      if (const KeyBinding* binding = find(path)) {
        assign(*binding, entry.second, config);
      } else if (known_paths().sections.contains(path)) {
        if (entry.second.IsNull()) continue;  // `imu:` with every child commented out
        if (!entry.second.IsMap()) {
          fail(entry.second, path, "expected a section of keys, got " + describe(entry.second));
        }
        walk(entry.second, path + ".", config);
      } else {
        std::string msg = source_ + ": unknown key '" + path + "'" + line_of(entry.first);
        if (const std::string hint = known_paths().closest(path); !hint.empty()) {
          msg += "; did you mean '" + hint + "'?";
        }
        throw ConfigError(msg);
      }
    }
  }

  static const KeyBinding* find(std::string_view path) {
    for (const KeyBinding& b : key_table()) {
      if (b.key == path) return &b;
    }
    return nullptr;
  }

  void assign(const KeyBinding& binding, const YAML::Node& node, Config& config) {
    if (auto scalar = std::get_if<double* (*)(Config&)>(&binding.target)) {
      *(*scalar)(config) = number(node, std::string(binding.key), binding.range);
      return;
    }
    if (auto optional = std::get_if<std::optional<double>* (*)(Config&)>(&binding.target)) {
      std::optional<double>& out = *(*optional)(config);
      if (node.IsNull()) {
        out.reset();  // `~`: back to unset
      } else {
        out = number(node, std::string(binding.key), binding.range);
      }
      return;
    }
    if (auto flag = std::get_if<bool* (*)(Config&)>(&binding.target)) {
      *(*flag)(config) = boolean(node, binding.key);
      return;
    }
    if (auto optional = std::get_if<std::optional<bool>* (*)(Config&)>(&binding.target)) {
      std::optional<bool>& out = *(*optional)(config);
      if (node.IsNull()) {
        out.reset();  // `~`: the platform decides
      } else {
        out = boolean(node, binding.key);
      }
      return;
    }
    if (auto platform = std::get_if<Platform* (*)(Config&)>(&binding.target)) {
      const auto p = node.IsScalar() ? platform_from_string(node.Scalar()) : std::nullopt;
      if (!p) {
        fail(node, binding.key,
             "expected one of generic, land, pedestrian, airborne, marine, got " + describe(node));
      }
      *(*platform)(config) = *p;
      return;
    }
    if (auto optional = std::get_if<std::optional<Vec3>* (*)(Config&)>(&binding.target)) {
      std::optional<Vec3>& out = *(*optional)(config);
      if (node.IsNull()) {
        out.reset();  // `~`: back to unset
      } else {
        out = vec3(node, binding);
      }
      return;
    }
    *std::get<Vec3* (*)(Config&)>(binding.target)(config) = vec3(node, binding);
  }

  Vec3 vec3(const YAML::Node& node, const KeyBinding& binding) {
    Vec3 out{};
    if (!node.IsSequence() || node.size() != out.size()) {
      fail(node, binding.key, "expected a list of 3 numbers, got " + describe(node));
    }
    for (std::size_t i = 0; i < out.size(); ++i) {
      out[i] = number(node[i], std::string(binding.key) + "[" + std::to_string(i) + "]",
                      binding.range);
    }
    return out;
  }

  // Only `true` and `false`: YAML 1.1's yes/no/on/off (and `1`, a quoted "true") are more often a
  // slip than a wish, and yaml-cpp would read some of them as switches.
  bool boolean(const YAML::Node& node, std::string_view key) {
    if (node.IsScalar() && node.Tag() != "!") {
      if (node.Scalar() == "true") return true;
      if (node.Scalar() == "false") return false;
    }
    fail(node, key, "expected true or false, got " + describe(node));
  }

  double number(const YAML::Node& node, const std::string& key, const ValueRange& range) {
    if (!node.IsScalar()) fail(node, key, "expected a number, got " + describe(node));
    // A quoted scalar ("5") is a string to YAML; taking it as a number would hide a typo'd
    // quote, so it is a type error like any other string. yaml-cpp tags quoted scalars "!".
    if (node.Tag() == "!") fail(node, key, "expected a number, got the string " + describe(node));

    std::string_view text = node.Scalar();
    if (text.starts_with('+')) text.remove_prefix(1);  // YAML allows it, from_chars does not
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    const bool yaml_special = lower == ".inf" || lower == "-.inf" || lower == ".nan";
    if (yaml_special || (ec == std::errc() && end == text.data() + text.size() &&
                         !std::isfinite(value))) {
      fail(node, key, "expected a finite number, got " + describe(node));
    }
    if (ec == std::errc::result_out_of_range) {
      fail(node, key, "number out of range: " + describe(node));
    }
    if (ec != std::errc() || end != text.data() + text.size()) {
      fail(node, key, "expected a number, got " + describe(node));
    }
    if (!range.contains(value)) fail(node, key, "must be " + range.describe() + ", got " + node.Scalar());
    return value;
  }

  std::string source_;
};

}  // namespace

Config load_from_string(const std::string& yaml_text, const std::string& source_name) {
  return Loader(source_name).load(yaml_text);
}

Config load_from_file(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    throw ConfigError(path + ": cannot open config file: " + std::strerror(errno));
  }
  std::string text;
  char chunk[4096];
  std::size_t n = 0;
  while ((n = std::fread(chunk, 1, sizeof chunk, file)) > 0) text.append(chunk, n);
  const bool failed = std::ferror(file) != 0;
  const int err = errno;
  std::fclose(file);
  if (failed) throw ConfigError(path + ": cannot read config file: " + std::strerror(err));
  return load_from_string(text, path);
}

}  // namespace navfuse::config
