// Registration of the Unicore UM220-INS front-end with the apps (format "unicore").
#pragma once

#include "frontends/common/frontend_info.hpp"

namespace navfuse::frontends::unicore {

// probe(): number of checksummed sentences in the head whose name this front-end knows;
// make_decoder(): UnicoreDecoder with default options;
// make_encoder(): UnicoreEncoder with default options (h51 dialect).
const FrontendInfo& frontend();

}  // namespace navfuse::frontends::unicore
