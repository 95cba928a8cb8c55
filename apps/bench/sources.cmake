# apps/bench: `navfuse bench` (device solution vs navfuse vs truth: alignment, metrics, report).
# report.py is compiled in (embed_text.cmake) so that an installed navfuse can render reports.
set(_bench_report_cpp ${CMAKE_CURRENT_BINARY_DIR}/bench/report_script.cpp)
add_custom_command(
  OUTPUT ${_bench_report_cpp}
  COMMAND ${CMAKE_COMMAND} -DIN=${CMAKE_CURRENT_LIST_DIR}/report.py -DOUT=${_bench_report_cpp}
          -DNAME=report_script -DNAMESPACE=navfuse::apps::bench -P ${CMAKE_CURRENT_LIST_DIR}/embed_text.cmake
  DEPENDS ${CMAKE_CURRENT_LIST_DIR}/report.py ${CMAKE_CURRENT_LIST_DIR}/embed_text.cmake
  COMMENT "Embedding apps/bench/report.py")
target_sources(navfuse_apps PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/bench.cpp
  ${CMAKE_CURRENT_LIST_DIR}/bench_analysis.cpp
  ${CMAKE_CURRENT_LIST_DIR}/bench_command.cpp
  ${CMAKE_CURRENT_LIST_DIR}/bench_log.cpp
  ${CMAKE_CURRENT_LIST_DIR}/error_metrics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fail_threshold.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pair_comparison.cpp
  ${CMAKE_CURRENT_LIST_DIR}/phase_split.cpp
  ${CMAKE_CURRENT_LIST_DIR}/phase_timeline.cpp
  ${CMAKE_CURRENT_LIST_DIR}/report_renderer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/series_csv.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solution_timing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/solution_track.cpp
  ${CMAKE_CURRENT_LIST_DIR}/time_alignment.cpp
  ${CMAKE_CURRENT_LIST_DIR}/truth_reference.cpp
  ${_bench_report_cpp})
