#include "apps/run/build_info.hpp"

#include <sys/utsname.h>

// Set for this file only by apps/run/sources.cmake from the CMake project and toolchain.
#ifndef NAVFUSE_VERSION
#error "NAVFUSE_VERSION must be defined by the build (apps/run/sources.cmake)"
#endif

namespace navfuse::apps {

std::string_view navfuse_version() { return NAVFUSE_VERSION; }

std::string build_description() {
  return "navfuse " + std::string(navfuse_version()) + " (" + NAVFUSE_BUILD_TYPE + ", " + NAVFUSE_COMPILER + ")";
}

std::string host_os_description() {
  utsname u{};
  if (::uname(&u) != 0) return {};
  return std::string(u.sysname) + " " + u.release;
}

}  // namespace navfuse::apps
