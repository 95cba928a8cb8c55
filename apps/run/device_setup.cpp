#include "apps/run/device_setup.hpp"

#include "apps/common/frontend_registry.hpp"

namespace navfuse::apps {

std::vector<SetupStep> device_setup_steps(std::string_view format, const config::Config& config) {
  const frontends::FrontendInfo* f = find_frontend(format);
  if (f == nullptr || f->setup_steps == nullptr) return {};
  return f->setup_steps(config);
}

std::string find_refusal(std::string_view format, std::span<const std::uint8_t> reply_bytes) {
  const frontends::FrontendInfo* f = find_frontend(format);
  if (f == nullptr || f->find_refusal == nullptr) return {};
  return f->find_refusal(reply_bytes);
}

}  // namespace navfuse::apps
