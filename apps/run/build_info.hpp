// What this navfuse binary is: its release (CMake project version) and how it was built, for
// `--version` and for the version a device-emulating link reports (FusionEngine VersionInfo,
// spec §3.7.3 L2588-2611).
#pragma once

#include <string>
#include <string_view>

namespace navfuse::apps {

// "0.1.0": the CMake project VERSION, so the binary never states a version by hand.
std::string_view navfuse_version();
// "navfuse 0.1.0 (Release, GNU 13.2.0)": release, build type and compiler.
std::string build_description();
// The host's operating system and kernel as uname(2) reports them ("Linux 6.8.0-45-generic"),
// empty when it cannot say.
std::string host_os_description();

}  // namespace navfuse::apps
