// Registration of the FusionEngine front-end with the apps (`navfuse decode`, replay, sim).
#pragma once

#include "frontends/common/stream_decoder.hpp"

namespace navfuse::frontends {

// format "fe": probe() counts CRC-valid FusionEngine frames in the head bytes; make_decoder()
// returns a fe::FusionEngineDecoder, make_encoder() a fe::FusionEngineEncoder.
const FrontendInfo& fusionengine_frontend();

}  // namespace navfuse::frontends
