// The check a command makes before it opens anything: no output may overwrite one of the
// command's inputs (`navfuse replay mine.vnb --csv mine.vnb` would destroy the recording), and
// no two outputs may name the same file (each would replace the other's bytes).
//
// "The same file" is the same device and inode, symlinks followed, for paths that exist; for
// outputs not yet created it is the same absolute, normalised path. Outputs written in place
// (devices, FIFOs, /dev and /proc paths: apps/output/output_file.hpp) are not checked: two
// outputs to /dev/null are fine, and a terminal may be both stdin and stdout.
#pragma once

#include <string>
#include <vector>

namespace navfuse::apps {

struct NamedOutput {
  std::string option;  // "--csv", for the message
  std::string path;    // empty: not requested (skipped)
};

// Throws CommandError naming the option and both paths when an output is an input or two
// outputs are one file.
void check_output_paths(const std::vector<std::string>& input_paths, const std::vector<NamedOutput>& outputs);

}  // namespace navfuse::apps
