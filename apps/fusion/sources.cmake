# apps/fusion: the fusion loop shared by `replay`, `bench` and `run` (time-base gate, counts,
# engine, epochs, output rate, run statistics) and the log merge that feeds replay and bench.
target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/fusion_runner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gnss_outage_plan.cpp
  ${CMAKE_CURRENT_LIST_DIR}/log_fusion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/measurement_counts.cpp
  ${CMAKE_CURRENT_LIST_DIR}/measurement_merger.cpp
  ${CMAKE_CURRENT_LIST_DIR}/merger_thread.cpp)
