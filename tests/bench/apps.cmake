# apps: end-to-end `navfuse replay` throughput (decode, merge, filter, FusionEngine output).
navfuse_add_benchmark(apps_replay_bench SOURCES ${CMAKE_CURRENT_LIST_DIR}/apps_replay_bench.cpp LIBS navfuse_apps)
