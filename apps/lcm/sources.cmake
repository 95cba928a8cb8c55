# apps/lcm: the LCM side of the engine (DESIGN.md "LCM"): core types -> navfuse LCM messages,
# publishing on NAVFUSE_POSE/STATUS/IMU/GNSS, and aiding received on NAVFUSE_AID_*.
target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/lcm_aiding_subscriber.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lcm_messages.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lcm_pose_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lcm_publisher.cpp)
target_link_libraries(navfuse_apps PUBLIC navfuse_lcm)
# lcm-gen 1.3's C++ for types that contain other types (status_t) compares a void* with a
# function pointer, which -Wpedantic flags. The generated code is not ours to change, so its
# headers are read as system headers (GCC and Clang drop the -I of a directory that is also
# -isystem).
target_include_directories(navfuse_apps SYSTEM PUBLIC ${PROJECT_BINARY_DIR}/generated/lcm)
