target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/calibration_groups.cpp
  ${CMAKE_CURRENT_LIST_DIR}/command_help.cpp
  ${CMAKE_CURRENT_LIST_DIR}/frontend_registry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gps_week_inference.cpp
  ${CMAKE_CURRENT_LIST_DIR}/input_bytes.cpp
  ${CMAKE_CURRENT_LIST_DIR}/input_spec.cpp
  ${CMAKE_CURRENT_LIST_DIR}/interrupt_signals.cpp
  ${CMAKE_CURRENT_LIST_DIR}/measurement_fields.cpp
  ${CMAKE_CURRENT_LIST_DIR}/progress_bar.cpp
  ${CMAKE_CURRENT_LIST_DIR}/recording_format.cpp
  ${CMAKE_CURRENT_LIST_DIR}/rejection_warning.cpp
  ${CMAKE_CURRENT_LIST_DIR}/summary.cpp)
