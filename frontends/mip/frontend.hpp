// Registration of the MIP (MicroStrain CV7) front-end with the apps: format "mip".
#pragma once

#include "frontends/common/frontend_info.hpp"

namespace navfuse::frontends::mip {

// probe(): number of complete, checksum- and field-walk-valid MIP packets in the head bytes.
// make_decoder(): MipDecoder with default options. make_encoder(): MipEncoder.
const FrontendInfo& frontend();

}  // namespace navfuse::frontends::mip
