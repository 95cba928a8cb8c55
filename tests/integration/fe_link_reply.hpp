// What a test reads back from the nav process's FusionEngine link: the frames of a reply or a
// streamed epoch, and the epochs it streams. Shared by the link's tests.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "apps/fusion/output_epoch.hpp"
#include "frontends/fusionengine/framer.hpp"
#include "frontends/fusionengine/message_catalog.hpp"

namespace navfuse::apps::testing {

namespace fe = frontends::fusionengine;

struct Reply {
  std::vector<std::uint16_t> types;
  std::vector<std::uint32_t> sequences;
  std::vector<std::vector<std::uint8_t>> payloads;
  // The frames other than the status messages only a device link sends.
  Reply without_status() const {
    Reply r;
    for (std::size_t i = 0; i < types.size(); ++i) {
      if (types[i] == fe::to_u16(fe::MessageType::kCalibrationStatus) ||
          types[i] == fe::to_u16(fe::MessageType::kSystemStatus)) {
        continue;
      }
      r.types.push_back(types[i]);
      r.payloads.push_back(payloads[i]);
    }
    return r;
  }
  std::size_t count(fe::MessageType type) const {
    return static_cast<std::size_t>(std::count(types.begin(), types.end(), fe::to_u16(type)));
  }
};

inline Reply parse_reply(const std::vector<std::uint8_t>& bytes) {
  Reply r;
  fe::Framer framer;
  framer.feed(bytes, [&](const fe::Frame& f) {
    r.types.push_back(f.header.message_type);
    r.sequences.push_back(f.header.sequence);
    r.payloads.emplace_back(f.payload.begin(), f.payload.end());
  });
  return r;
}

// An epoch every 100 ms from 1 s, a pose at each.
inline OutputEpoch epoch_at(int k) {
  OutputEpoch e;
  e.solution.header.time_ns = 1'000'000'000LL + k * 100'000'000LL;
  e.solution.header.valid = NavSolution::kValidAttitude;
  e.pose_due = true;
  return e;
}

}  // namespace navfuse::apps::testing

namespace navfuse::apps {
// The link tests' own names for these (test-only header).
using testing::epoch_at;
using testing::parse_reply;
using testing::Reply;
}  // namespace navfuse::apps
