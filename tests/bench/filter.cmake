# Filter: full engine loop on a 200 Hz IMU + 10 Hz GNSS + 10 Hz speed stream (IMU samples/s).
if(TARGET navfuse_sim)
  navfuse_add_benchmark(filter_engine_bench SOURCES ${CMAKE_CURRENT_LIST_DIR}/filter_engine_bench.cpp
                        LIBS navfuse_filter navfuse_sim)
endif()
