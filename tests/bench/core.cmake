# Core checks: CRC-32 kernels on FusionEngine-frame-sized and long buffers (bytes/s).
navfuse_add_benchmark(core_crc_bench SOURCES ${CMAKE_CURRENT_LIST_DIR}/core_crc_bench.cpp LIBS navfuse_core)
