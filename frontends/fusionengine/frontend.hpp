// Registration of the FusionEngine front-end with the apps (`navfuse decode`, replay, sim).
#pragma once

#include "frontends/common/frontend_info.hpp"

namespace navfuse::frontends::fusionengine {

// format "fe": probe() counts CRC-valid FusionEngine frames in the head bytes; make_decoder()
// returns a FusionEngineDecoder, make_encoder() a FusionEngineEncoder.
const FrontendInfo& frontend();

}  // namespace navfuse::frontends::fusionengine
