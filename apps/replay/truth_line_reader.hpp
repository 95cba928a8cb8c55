// Line-by-line reading of a reference file for the TruthRows readers: skips blank lines, drops
// a '\r', and makes errors that name the file and line.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>

#include "apps/common/command_error.hpp"
#include "frontends/common/text_fields.hpp"

namespace navfuse::apps {

class TruthLineReader {
 public:
  explicit TruthLineReader(const std::string& path) : path_(path), in_(path) {
    if (!in_) throw CommandError("cannot open truth file '" + path + "'");
  }
  // The next line that is not blank; false at the end of the file.
  bool next(std::string_view& line) {
    while (std::getline(in_, line_)) {
      ++line_number_;
      line = line_;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (!frontends::text::is_blank_line(line)) return true;
    }
    return false;
  }
  CommandError error(std::string_view what) const {
    return CommandError("truth file '" + path_ + "' line " + std::to_string(line_number_) + ": " + std::string(what));
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ifstream in_;
  std::string line_;
  std::uint64_t line_number_ = 0;
};

}  // namespace navfuse::apps
