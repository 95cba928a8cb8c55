# FusionEngine framing + decoding throughput (goal: >= 1 GB/s on one core, median of runs).
navfuse_add_benchmark(navfuse_fe_bench
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/fusionengine_decode_bench.cpp
  LIBS navfuse_fusionengine)
