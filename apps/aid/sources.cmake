target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/aid_command.cpp
  ${CMAKE_CURRENT_LIST_DIR}/aid_message.cpp)
target_link_libraries(navfuse_apps PUBLIC navfuse_lcm)
