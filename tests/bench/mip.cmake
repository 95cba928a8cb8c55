# MIP framing and framing+decoding throughput on a CV7-style 0x80/0x82 stream with 1% corrupted
# bytes (tests/bench/mip_bench.cpp).
navfuse_add_benchmark(navfuse_mip_bench SOURCES ${CMAKE_CURRENT_LIST_DIR}/mip_bench.cpp LIBS navfuse_mip)
