// Registration of the KF-GINS-style IMU text reader with the apps: format "imutxt".
#pragma once

#include "frontends/common/frontend_info.hpp"

namespace navfuse::frontends::imutxt {

// probe(): number of consecutive plausible sample lines in the head bytes (seconds of week that
// increase by less than a second, increments of at most 1 rad and 50 m/s per sample: what no
// RTKLIB, NMEA or Unicore line looks like). make_decoder(): imutxt::ImuTextDecoder without a week
// (bare seconds of week); make_decoder_in_week(): with the GPS week. No encoder.
const FrontendInfo& frontend();

}  // namespace navfuse::frontends::imutxt
