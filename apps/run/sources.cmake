# apps/run: `navfuse run`, the live nav process (inputs, filter thread, outputs, LCM, status).
target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/build_info.cpp
  ${CMAKE_CURRENT_LIST_DIR}/corrections_forwarder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/device_setup.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fe_device_emulator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fe_device_status.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fe_link_inputs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/input_endpoint.cpp
  ${CMAKE_CURRENT_LIST_DIR}/input_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/input_recorder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/latency_tracker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lcm_service.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mip_device_emulator.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nav_process.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ntrip_protocol.cpp
  ${CMAKE_CURRENT_LIST_DIR}/output_sink.cpp
  ${CMAKE_CURRENT_LIST_DIR}/process_priority.cpp
  ${CMAKE_CURRENT_LIST_DIR}/realtime_pacer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/rover_position.cpp
  ${CMAKE_CURRENT_LIST_DIR}/run_command.cpp
  ${CMAKE_CURRENT_LIST_DIR}/run_log.cpp
  ${CMAKE_CURRENT_LIST_DIR}/status_reporter.cpp
  ${CMAKE_CURRENT_LIST_DIR}/termination_signals.cpp)
target_link_libraries(navfuse_apps PUBLIC navfuse_filter navfuse_lcm Threads::Threads)
# The version and toolchain the binary reports (apps/run/build_info.hpp), on this file only so
# that a version bump recompiles one file.
set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/build_info.cpp PROPERTIES COMPILE_DEFINITIONS
  "NAVFUSE_VERSION=\"${PROJECT_VERSION}\";NAVFUSE_BUILD_TYPE=\"${CMAKE_BUILD_TYPE}\";NAVFUSE_COMPILER=\"${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}\"")
