# apps/simcmd: `navfuse sim` (simulated device logs through the front-ends' encoders).
target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/device_solution_model.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sim_command.cpp)
target_link_libraries(navfuse_apps PUBLIC navfuse_sim)
