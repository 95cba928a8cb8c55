// The end of a command that ran without error but did not do what was asked (issue 15, "exit
// codes"): no frame decoded, no pose in navigation although poses were asked for, nothing to
// compare. It exits 2 with the reason, after the summary; --allow-empty, for scripts that treat
// an empty run as fine, prints the reason as a warning and keeps exit 0.
#pragma once

#include <iostream>
#include <string>
#include <string_view>

#include "apps/common/command_error.hpp"
#include "apps/common/summary.hpp"

namespace navfuse::apps {

inline constexpr int kExitNothingUseful = 2;
inline constexpr const char* kAllowEmptyHelp = "Exit 0 even when nothing useful came out (no frame, no navigation)";

// The error ending such a run: "<command> produced nothing useful: <reason>", exit 2.
inline CommandError nothing_useful_error(std::string_view command, const std::string& reason) {
  return CommandError(std::string(command) + " produced nothing useful: " + reason, kExitNothingUseful);
}

// With `allow_empty`, an exit-2 error becomes a warning on stderr and exit 0; any other error is
// rethrown.
inline int tolerate_empty(const CommandError& error, bool allow_empty) {
  if (!allow_empty || error.exit_code() != kExitNothingUseful) throw error;
  std::cerr << "navfuse: warning: " << error.what() << " (--allow-empty: exit 0)\n";
  return 0;
}

// Throws nothing_useful_error(command, reason), or with `allow_empty` warns and returns 0.
inline int nothing_useful(std::string_view command, const std::string& reason, bool allow_empty) {
  return tolerate_empty(nothing_useful_error(command, reason), allow_empty);
}

// "no frame decoded from vn:log.bin (...)" for an input without a single frame, else "".
inline std::string no_frame_reason(const InputSummary& in) {
  if (in.counters.frames > 0) return "";
  return "no frame decoded from " + in.format + ":" + in.path + " (" + std::to_string(in.counters.bytes) + " bytes, " +
         std::to_string(in.counters.skipped_bytes) + " skipped): is it empty, or the format prefix wrong?";
}

}  // namespace navfuse::apps
