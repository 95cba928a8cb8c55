# FusionEngine framing + decoding throughput (goal: >= 1 GB/s on one core, median of runs).
navfuse_add_benchmark(navfuse_fe_bench
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fusionengine_decode_bench.cpp
  LIBS navfuse_fusionengine)
# The same stream written to a file and framed from it, for tests/bench/fe_vendor_compare.sh
# (Point One's own parser on the same bytes). A plain program: it needs no Google Benchmark.
add_executable(navfuse_fe_bench_stream ${CMAKE_CURRENT_LIST_DIR}/fe_bench_stream.cpp)
target_link_libraries(navfuse_fe_bench_stream PRIVATE navfuse_fusionengine navfuse_build_flags)
