// The one check every LCM user of the command line makes after opening its handle (`run --lcm`,
// `replay --lcm`, `aid --lcm`): a handle that is not good() is a one-line error naming the URL.
#pragma once

#include <string>

#include <lcm/lcm-cpp.hpp>

#include "apps/common/command_error.hpp"

namespace navfuse::apps {

// `url` as given on the command line; empty means LCM's default (LCM_DEFAULT_URL or udpm).
inline void require_lcm_open(lcm::LCM& lcm, const std::string& url) {
  if (!lcm.good()) throw CommandError("--lcm: cannot open LCM '" + (url.empty() ? std::string("default") : url) + "'");
}

}  // namespace navfuse::apps
