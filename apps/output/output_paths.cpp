#include "apps/output/output_paths.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <optional>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {
namespace {

// What identifies an output file: its inode when it exists, else its normalised absolute path.
struct FileIdentity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string absolute;

  bool operator==(const FileIdentity& o) const {
    if (exists != o.exists) return false;
    return exists ? device == o.device && inode == o.inode : absolute == o.absolute;
  }
};

std::optional<struct stat> stat_of(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return st;
}

// Nothing for an output written in place (see output_file.hpp), which replaces nothing.
std::optional<FileIdentity> regular_output_identity(const std::string& path) {
  if (path == "-" || path.starts_with("/dev/") || path.starts_with("/proc/")) return std::nullopt;
  FileIdentity id;
  if (const auto st = stat_of(path)) {
    if (!S_ISREG(st->st_mode)) return std::nullopt;
    id.exists = true;
    id.device = st->st_dev;
    id.inode = st->st_ino;
  } else {
    std::error_code ec;
    id.absolute = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec).string();
    if (ec) id.absolute = path;
  }
  return id;
}

}  // namespace

void check_output_paths(const std::vector<std::string>& input_paths, const std::vector<NamedOutput>& outputs) {
  std::vector<std::pair<const NamedOutput*, FileIdentity>> seen;
  for (const NamedOutput& out : outputs) {
    if (out.path.empty()) continue;
    const auto id = regular_output_identity(out.path);
    if (!id) continue;
    if (id->exists) {
      for (const std::string& in : input_paths) {
        const auto st = stat_of(in);
        if (st && st->st_dev == id->device && st->st_ino == id->inode) {
          throw CommandError(out.option + " '" + out.path + "' is the input '" + in +
                             "': refusing to overwrite an input");
        }
      }
    }
    for (const auto& [other, other_id] : seen) {
      if (other_id == *id) {
        throw CommandError(out.option + " '" + out.path + "' and " + other->option + " '" + other->path +
                           "' are the same file: give each output its own");
      }
    }
    seen.emplace_back(&out, *id);
  }
}

}  // namespace navfuse::apps
