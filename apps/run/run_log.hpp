// One-line event messages of the nav process on stderr ("navfuse run: input ... reconnected").
// Several threads report events; the lock keeps their lines whole.
#pragma once

#include <string_view>

namespace navfuse::apps {

void log_event(std::string_view message);

}  // namespace navfuse::apps
