// Errors a command reports to the user: one line, naming the problem (file, key, URI...), and a
// non-zero exit. main() prints "navfuse: error: <what()>".
#pragma once

#include <stdexcept>

namespace navfuse::apps {

class CommandError : public std::runtime_error {
 public:
  explicit CommandError(const std::string& what, int exit_code = 1)
      : std::runtime_error(what), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

}  // namespace navfuse::apps
