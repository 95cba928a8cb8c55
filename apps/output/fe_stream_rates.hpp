// The FusionEngine messages navfuse streams (Pose 10000, PoseAux 10003, GNSSInfo 10001,
// IMUOutput 11000; and on a device-emulating link CalibrationStatus 10004 and SystemStatus
// 10500) with the rate each goes out at. All start at "default", which is the DESIGN.md
// --fe-out contract; a device-emulating link lets clients change them with SetMessageRate
// (spec L1419-1440), a file keeps the defaults. This is the one rate table of an FE stream.
//
// Like a device's, the table has an active and a saved copy: SetMessageRate with APPLY_AND_SAVE
// writes both, SaveConfig saves the active rates or reverts to the saved or default ones (spec
// L1336-1377: "the active configuration" includes the rates), and GetMessageRate reports either
// copy with ACTIVE_DIFFERS_FROM_SAVED per message (L1655-1690).
#pragma once

#include <array>
#include <cstdint>

#include "apps/output/output_rate.hpp"
#include "frontends/fusionengine/messages_control.hpp"

namespace navfuse::apps {

class FeStreamRates {
 public:
  struct Entry {
    frontends::fusionengine::MessageType type;
    frontends::fusionengine::MessageRate rate = frontends::fusionengine::MessageRate::kDefault;  // active
    frontends::fusionengine::MessageRate saved = frontends::fusionengine::MessageRate::kDefault;
    OutputRate interval{0.0};  // for interval rates (k10Ms ... k60S)
  };
  FeStreamRates();

  // False for a message navfuse does not stream (the device answers "unsupported"). With the
  // wildcard message id and an interval rate, only messages that are on change unless
  // `include_disabled` (the INCLUDE_DISABLED_MESSAGES flag, spec L1470-1476). `and_save`
  // (APPLY_AND_SAVE) writes the saved copy of each rate set as well.
  bool set(std::uint16_t message_id, frontends::fusionengine::MessageRate rate, bool include_disabled = false,
           bool and_save = false);
  frontends::fusionengine::MessageRate rate(frontends::fusionengine::MessageType type) const;
  // SaveConfig's three actions applied to the rates.
  void save();
  void revert_to_saved();
  void revert_to_default();  // also ResetRequest's RESET_CONFIG (spec L1355)
  // Whether `type` goes out at this epoch. `default_due` is when it would at its default rate,
  // `on_change` whether its content changed since it last went out.
  bool due(frontends::fusionengine::MessageType type, std::int64_t time_ns, bool default_due, bool on_change);
  const std::array<Entry, 6>& entries() const { return entries_; }

 private:
  Entry* find(frontends::fusionengine::MessageType type);
  static void assign(Entry& e, frontends::fusionengine::MessageRate rate);
  std::array<Entry, 6> entries_;
};

}  // namespace navfuse::apps
