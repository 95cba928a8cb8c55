# apps/output: the output layer of replay, bench and run: one epoch encoder per protocol
# (FusionEngine, MIP 0x82, NMEA) on top of the front-ends' encoders, the file writers (those encoders,
# CSV) and the output thread of replay.
target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/compensated_imu.cpp
  ${CMAKE_CURRENT_LIST_DIR}/csv_pose_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fe_epoch_encoder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fe_stream_rates.cpp
  ${CMAKE_CURRENT_LIST_DIR}/innovation_csv_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/mip_epoch_encoder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nmea_epoch_encoder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/output_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/output_paths.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pose_output_thread.cpp)
