// `--gps-week W` (DESIGN.md: replay, smooth, bench, decode): the GPS week of inputs timed by
// seconds of week only (imutxt). Optional: without it the week is taken from another input with
// GPS time (apps/common/gps_week_inference.hpp).
#pragma once

#include <cstdint>
#include <optional>

#include <CLI/CLI.hpp>

namespace navfuse::apps {

inline CLI::Option* add_gps_week_option(CLI::App* app, std::optional<std::int32_t>& week) {
  return app
      ->add_option("--gps-week", week,
                   "GPS week of imutxt inputs (seconds of week only); default: from another input with GPS time")
      ->check(CLI::Range(0, 10000));  // week 10000 is in 2171
}

}  // namespace navfuse::apps
