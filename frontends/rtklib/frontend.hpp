// Registration of the RTKLIB solution reader with the apps: format "rtklib".
#pragma once

#include "frontends/common/frontend_info.hpp"

namespace navfuse::frontends::rtklib {

// probe(): number of lines in the head bytes that read as RTKLIB solutions under the file's own
// header (plus one for a column header naming GPST/UTC/JST). make_decoder(): rtklib::PosDecoder.
// No encoder.
const FrontendInfo& frontend();

}  // namespace navfuse::frontends::rtklib
