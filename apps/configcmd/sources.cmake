target_sources(navfuse_apps PRIVATE ${CMAKE_CURRENT_LIST_DIR}/config_command.cpp)
