# apps/output: pose writers (FusionEngine, MIP 0x82, CSV) on top of the front-ends' encoders.
target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/csv_pose_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fe_pose_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mip_pose_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/output_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pose_output_thread.cpp)
