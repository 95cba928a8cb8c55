# apps/bench: `navfuse bench` (device solution vs navfuse vs truth: alignment, metrics, report).
target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/bench_analysis.cpp
  ${CMAKE_CURRENT_LIST_DIR}/bench_log.cpp
  ${CMAKE_CURRENT_LIST_DIR}/error_metrics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pair_comparison.cpp
  ${CMAKE_CURRENT_LIST_DIR}/phase_split.cpp
  ${CMAKE_CURRENT_LIST_DIR}/phase_timeline.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solution_timing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solution_track.cpp
  ${CMAKE_CURRENT_LIST_DIR}/time_alignment.cpp
  ${CMAKE_CURRENT_LIST_DIR}/truth_reference.cpp)
