#include "apps/common/frontend_registry.hpp"

#include "frontends/fusionengine/frontend.hpp"
#include "frontends/imutxt/frontend.hpp"
#include "frontends/mip/frontend.hpp"
#include "frontends/rtklib/frontend.hpp"
#include "frontends/unicore/frontend.hpp"
#include "frontends/vectornav/frontend.hpp"

namespace navfuse::apps {

const std::vector<const frontends::FrontendInfo*>& frontends_list() {
  static const std::vector<const frontends::FrontendInfo*> list = [] {
    // Binary protocols first: on a tie in valid frames the one with the stronger check wins
    // (CRC-32, then Fletcher, then CRC-16 / XOR-checked ASCII). The unchecked research text
    // formats come last: they win only where no checked frame is found.
    return std::vector<const frontends::FrontendInfo*>{
        &frontends::fusionengine::frontend(), &frontends::mip::frontend(),
        &frontends::vectornav::frontend(), &frontends::unicore::frontend(),
        &frontends::rtklib::frontend(), &frontends::imutxt::frontend()};
  }();
  return list;
}

const frontends::FrontendInfo* find_frontend(std::string_view format) {
  for (const auto* f : frontends_list()) {
    if (f->format == format) return f;
  }
  return nullptr;
}

std::string known_formats() {
  std::string s;
  for (const auto* f : frontends_list()) {
    if (!s.empty()) s += ", ";
    s += f->format;
  }
  return s.empty() ? std::string("(none)") : s;
}

std::vector<std::string> writable_formats() {
  std::vector<std::string> formats;
  for (const auto* f : frontends_list()) {
    if (f->make_encoder != nullptr) formats.emplace_back(f->format);
  }
  return formats;
}

const frontends::FrontendInfo* odometry_input_frontend() {
  for (const auto* f : frontends_list()) {
    if (f->odometry_input && f->make_encoder != nullptr) return f;
  }
  return nullptr;
}

const frontends::FrontendInfo* detect_format(std::span<const std::uint8_t> head) {
  const frontends::FrontendInfo* best = nullptr;
  std::size_t best_frames = 0;
  for (const auto* f : frontends_list()) {
    const std::size_t n = f->probe(head);
    if (n > best_frames) {
      best = f;
      best_frames = n;
    }
  }
  return best;
}

}  // namespace navfuse::apps
