# apps/replay: `navfuse replay` (input merge, filter run, pose outputs, accuracy against truth).
target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/calibration_collector.cpp
  ${CMAKE_CURRENT_LIST_DIR}/calibration_hook.cpp
  ${CMAKE_CURRENT_LIST_DIR}/calibration_output.cpp
  ${CMAKE_CURRENT_LIST_DIR}/error_stats.cpp
  ${CMAKE_CURRENT_LIST_DIR}/replay.cpp
  ${CMAKE_CURRENT_LIST_DIR}/replay_command.cpp
  ${CMAKE_CURRENT_LIST_DIR}/smoothed_pass.cpp
  ${CMAKE_CURRENT_LIST_DIR}/truth_accuracy.cpp
  ${CMAKE_CURRENT_LIST_DIR}/truth_csv_rows.cpp
  ${CMAKE_CURRENT_LIST_DIR}/truth_nav_rows.cpp
  ${CMAKE_CURRENT_LIST_DIR}/truth_rows.cpp
  ${CMAKE_CURRENT_LIST_DIR}/truth_rtklib_rows.cpp
  ${CMAKE_CURRENT_LIST_DIR}/truth_track.cpp)
target_link_libraries(navfuse_apps PUBLIC navfuse_filter)
