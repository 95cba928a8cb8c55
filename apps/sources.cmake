# navfuse_apps: everything behind the `navfuse` command line, as a library so integration tests
# can drive the commands in-process. Each part lists its own sources in <part>/sources.cmake.
add_library(navfuse_apps STATIC)
target_link_libraries(navfuse_apps PUBLIC navfuse_frontends navfuse_core CLI11::CLI11 nlohmann_json::nlohmann_json)
foreach(part common fusion decode replay run aid simcmd bench output lcm configcmd)
  include(${CMAKE_CURRENT_SOURCE_DIR}/${part}/sources.cmake OPTIONAL)
endforeach()

add_executable(navfuse main.cpp)
# Ceres comes in through navfuse_calibration, linked here only (apps/replay/calibration_hook.hpp).
target_link_libraries(navfuse PRIVATE navfuse_apps navfuse_calibration navfuse_build_flags)
